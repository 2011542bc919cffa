// The faces of a mesh around the holes being filled, for the intersection checks
// (patch_intersections.h): grids (face_grid.h) over the faces near given regions only, so that
// checking the patches costs what their neighbourhoods hold. A grid over every face of the mesh
// cost more than the checks it served (sorting a cell key per face: an eighth of filling four
// small holes in a 1.4M-face mesh). A lookup outside every region so far files the faces near it
// on demand, so every lookup finds what a scan of all the faces would.
#pragma once

#include <utility>
#include <vector>

#include "box_buckets.h"
#include "face_grid.h"
#include "holefill/mesh.h"
#include "holefill/progress.h"

namespace holefill::detail {

// The box of the loop's vertices grown on every side by its largest extent: where a patch across
// the loop lies (refinement and umbrella smoothing stay inside the loop's box; fairing may bulge
// out of it, and the index then files the faces near the bulge when it is looked up).
Box neighbourhood_of(const Mesh& mesh, const std::vector<VertexHandle>& loop);

class MeshFaceIndex {
 public:
  // Indexes the faces the mesh has now (those not deleted), filing at once, in one pass over the
  // mesh, the faces near `regions`. The mesh must outlive the index, and the faces indexed must
  // keep their indices and corners (filling only adds faces after them); faces added to the mesh
  // later are found only once add() is told of them. The pass runs on up to `threads` threads
  // (the faces in blocks, filed in order: the same index on any number). It enters
  // phase::kIndexingFaces and, once `progress` is cancelled, stops at the next block of faces:
  // the index is then incomplete, and the caller must drop it unused.
  MeshFaceIndex(const Mesh& mesh, const std::vector<Box>& regions, unsigned threads = 1,
                const Progress* progress = nullptr);

  // An entry added after the index was made (a finished patch's face, id = its index): found by
  // every lookup whose box it overlaps.
  void add(int id, const Box& box) { added_.add(id, box); }

  // Whether an entry added since the index was made overlaps `box`.
  bool added_overlaps(const Box& box) const;

  // The ids (face indices) of the indexed faces and added entries whose boxes overlap `box`,
  // ascending, each once. A box that no region holds first files the faces near it (a pass over
  // the mesh).
  std::vector<int> near(const Box& box) const;

  // How many faces the index has filed so far, counted once per region set that filed them: the
  // faces whose boxes overlap a region (and faces spanning many of the region grid's cells).
  std::size_t filed_faces() const;

  // A view of `whole` for one hole filled apart from the mesh (patch_apart.h): the same mesh,
  // faces and ids, for lookups inside `region` (one of the regions `whole` was made with); each
  // lookup's box is added to looked_up(), and one outside the region finds nothing and sets
  // looked_outside(). A view only reads `whole`, so views on several threads may share it while
  // nothing changes it; `whole` must outlive the view.
  MeshFaceIndex(const MeshFaceIndex& whole, const Box& region);
  const Box& looked_up() const { return looked_up_; }
  bool looked_outside() const { return looked_outside_; }

  // The mesh whose faces the ids number.
  const Mesh& mesh() const { return mesh_; }

  // How many threads one check through this index may use (patch_intersections.h; 1 unless set,
  // a view's its whole's): the threads fill_holes has left over when it has fewer holes than
  // threads.
  void set_threads(unsigned threads) { threads_ = threads; }
  unsigned threads() const { return whole_ ? whole_->threads() : threads_; }

 private:
  // The faces near some regions, in one grid; `everywhere` when a region was not a finite box
  // (then every face is filed, as a NaN box overlaps every box). The regions too are in a grid,
  // so that finding the part that holds a lookup does not test every hole's region.
  struct Part {
    std::vector<Box> regions;
    bool everywhere = false;
    FaceGrid grid;
    FaceGrid region_grid;
    std::size_t faces = 0;
  };
  const Part& part_holding(const Box& box) const;
  void file_faces_near(std::vector<Box> regions, unsigned threads = 1,
                       const Progress* progress = nullptr) const;

  const Mesh& mesh_;
  int indexed_faces_;                // the faces below this index (those not deleted) are indexed
  mutable std::vector<Part> parts_;  // grown by lookups (the index is read by one thread)
  BoxBuckets added_;
  unsigned threads_ = 1;
  // A view's (otherwise null and unused).
  const MeshFaceIndex* whole_ = nullptr;
  Box view_region_;
  mutable Box looked_up_;
  mutable bool looked_outside_ = false;
};

}  // namespace holefill::detail
