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

class FaceGrid {
 public:
  // Files each (id, box) under the cells its box touches; cells are twice the boxes' mean extent.
  explicit FaceGrid(std::vector<std::pair<int, Box>> boxes);

  // The ids of the entries whose boxes overlap `box`, ascending, each once.
  std::vector<int> near(const Box& box) const;

 private:
  struct CellRange {
    std::array<std::int64_t, 3> low, high;
    double cells;  // how many (a double: it can be huge)
  };
  std::optional<CellRange> cell_range(const Box& box) const;

  double cell_ = 1.0;
  std::vector<std::pair<int, Box>> entries_;
  std::vector<std::pair<std::uint64_t, std::size_t>> cells_;  // (cell key, entry), sorted
  std::vector<std::size_t> unfiled_;                          // entries in no cell: too large
};

}  // namespace holefill::detail
