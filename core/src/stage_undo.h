// Undoing a pipeline stage on one patch: what fill.cpp needs to take back a refinement or a
// smoothing that made the patch worse (a degenerate triangle, a new intersection).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "holefill/mesh.h"
#include "holefill/patch.h"

namespace holefill::detail {

// Whether the patch's faces, new vertices and new edges are the newest elements of the mesh, so
// that deleting them and collecting garbage moves no other element.
bool patch_is_newest(const Mesh& mesh, const Patch& patch);

// Whether some face of the patch is degenerate (zero area, measure_triangle's test); a large
// patch's faces looked at in blocks on up to `threads` threads.
bool has_degenerate_face(const Mesh& mesh, const Patch& patch, unsigned threads = 1);

// What a stage can be undone to: the patch's triangles and vertices as they are now, or, when
// the patch is not the newest part of the mesh (a viewer stepping holes in turn), the whole mesh.
class StageUndo {
 public:
  StageUndo(const Mesh& mesh, const Patch& patch);

  // Puts the mesh and `patch` back as they were when this was made; every element outside the
  // patch keeps its index.
  void undo(Mesh& mesh, Patch& patch) const;

 private:
  Patch patch_;
  std::optional<Mesh> whole_mesh_;
  std::vector<std::array<VertexHandle, 3>> triangles_;
  std::vector<Stage> face_stages_;
  std::vector<Point> positions_;
};

}  // namespace holefill::detail
