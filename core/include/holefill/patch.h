// A patch: the triangles and vertices that filling one hole added to the mesh. The mesh also
// carries per-element tags (OpenMesh properties) saying which stage created each patch face and
// vertex, so a renderer can colour stages without knowing about patches.
#pragma once

#include <cstdint>
#include <vector>

#include "holefill/mesh.h"

namespace holefill {

enum class Stage : std::uint8_t { Original = 0, Triangulated = 1, Refined = 2, Smoothed = 3 };

const char* to_string(Stage stage);

struct Patch {
  int hole_id = -1;
  Stage stage = Stage::Original;           // the last stage run on this patch
  std::vector<VertexHandle> boundary;      // the hole's loop, P0 ... Pn-1
  std::vector<FaceHandle> faces;           // every face of the patch
  std::vector<VertexHandle> new_vertices;  // vertices the patch added; the only ones that move
};

// Named properties on the mesh: found when present, added otherwise.
struct PatchTags {
  explicit PatchTags(Mesh& mesh);
  OpenMesh::FPropHandleT<std::uint8_t> face_stage;    // Stage that created the face
  OpenMesh::VPropHandleT<std::uint8_t> vertex_stage;  // Stage that created the vertex
  OpenMesh::VPropHandleT<double> scale;               // Liepa's sigma, for refinement
};

// Reads the face stage tag without adding properties; Original where the mesh has no tags.
Stage face_stage(const Mesh& mesh, FaceHandle face);
}  // namespace holefill
