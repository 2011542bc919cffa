// A uniform grid over the bounding boxes of faces (a patch's triangles, the mesh's faces near the
// holes: mesh_face_index.h), so that the faces near a box are found without scanning them all for
// every stage of every hole. The arithmetic is safe for
// any coordinates, however large: a box whose cells cannot be counted in finite numbers is kept
// in a list that every lookup scans.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "holefill/mesh.h"

namespace holefill::detail {

struct Box {
  Point low{INFINITY, INFINITY, INFINITY}, high{-INFINITY, -INFINITY, -INFINITY};
  void add(const Point& p) {
    low.minimize(p);
    high.maximize(p);
  }
  void add(const Box& box) {
    add(box.low);
    add(box.high);
  }
  void grow(double margin) {
    low -= Point(margin, margin, margin);
    high += Point(margin, margin, margin);
  }
  bool overlaps(const Box& other) const {
    for (int axis = 0; axis < 3; ++axis) {
      if (high[axis] < other.low[axis] || other.high[axis] < low[axis]) return false;
    }
    return true;
  }
  // The largest absolute coordinate inside (0 for an empty box).
  double magnitude() const;
};

Box box_of(const Mesh& mesh, FaceHandle face);

// The cells of a uniform grid of side `cell` that a box touches, shared by FaceGrid and
// BoxBuckets (box_buckets.h). Indices grow with the coordinates and are clamped (infinities too)
// so that they fit in 64 bits; boxes that overlap share a cell.
struct CellSpan {
  std::array<std::int64_t, 3> low, high;
  double count;  // how many cells (a double: it can be huge)
};
// Nothing when a coordinate is NaN (such a box has no cell).
std::optional<CellSpan> cell_span(const Box& box, double cell);
// A cell's hash key: 21 bits per axis, so distant cells may share a key, which only adds
// candidates. Below 2^63: never FlatIndexMap's empty key.
std::uint64_t cell_key(std::int64_t x, std::int64_t y, std::int64_t z);
// Calls visit(key) for each cell of `span`.
template <class Visit>
void for_each_cell_key(const CellSpan& span, const Visit& visit) {
  for (auto x = span.low[0]; x <= span.high[0]; ++x) {
    for (auto y = span.low[1]; y <= span.high[1]; ++y) {
      for (auto z = span.low[2]; z <= span.high[2]; ++z) visit(cell_key(x, y, z));
    }
  }
}

class FaceGrid {
 public:
  // Files each (id, box) under the cells its box touches; cells are twice the boxes' mean extent.
  // On up to `threads` threads, the same grid on any number.
  explicit FaceGrid(std::vector<std::pair<int, Box>> boxes, unsigned threads = 1);

  // The ids of the entries whose boxes overlap `box`, ascending, each once.
  std::vector<int> near(const Box& box) const;

 private:
  double cell_ = 1.0;
  std::vector<std::pair<int, Box>> entries_;
  std::vector<std::pair<std::uint64_t, std::size_t>> cells_;  // (cell key, entry), sorted
  std::vector<std::size_t> unfiled_;                          // entries in no cell: too large
};

}  // namespace holefill::detail
