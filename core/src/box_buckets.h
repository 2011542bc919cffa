// Boxes added one at a time and looked up by overlap: the patch faces MeshFaceIndex learns of as
// holes are filled (mesh_face_index.h). Each box is filed under the cells of a fixed hashed grid
// that it touches, so a lookup tests the boxes of its own cells, not every box added so far (a
// scan of them all after each stage of each hole made filling 20,000 holes quadratic). A box with
// a NaN coordinate, or spanning too many cells, is kept in a list every lookup tests; a lookup
// spanning too many cells tests every box. Either way a lookup finds exactly the boxes a scan
// would.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "face_grid.h"
#include "flat_index_map.h"

namespace holefill::detail {

class BoxBuckets {
 public:
  // Cells of `cell` on every side; a cell that is not finite and positive is taken from the
  // first box added (a few times its extent).
  explicit BoxBuckets(double cell = 0.0);

  void add(int id, const Box& box);

  // Appends the ids of the boxes added that overlap `box` (Box::overlaps), each once, in no
  // particular order; returns how many it appended.
  std::size_t append_overlapping(const Box& box, std::vector<int>& ids) const;

  std::size_t size() const { return entries_.size(); }

 private:
  static constexpr int kNoLink = -1;
  struct Link {
    int entry, next;  // the next link of the same cell, or kNoLink
  };

  double cell_;
  std::vector<std::pair<int, Box>> entries_;
  FlatIndexMap first_link_;  // cell key -> its first link
  std::vector<Link> links_;
  std::vector<int> wide_;  // entries in no cell: not finite, or spanning too many cells
};

}  // namespace holefill::detail
