// Boxes (the mesh faces' around a hole) in a bounding-box hierarchy, asked which of them a line
// segment may cross: the chords of a hole's polygon through the mesh (patch_intersections.h). A
// uniform grid looked up by a chord's bounding box returned every face in that box, which for a
// hole of a thousand edges (half a million chords, most across the hole) took many minutes; the
// hierarchy visits only the boxes along the segment.
#pragma once

#include <utility>
#include <vector>

#include "face_grid.h"

namespace holefill::detail {

class SegmentBoxTree {
 public:
  explicit SegmentBoxTree(std::vector<std::pair<int, Box>> boxes);

  // Calls visit(id) for every box the segment [a, b] meets (and some it passes very close to:
  // the test is conservative, never the other way), until visit returns true; returns whether
  // one did. A box with a NaN coordinate is always visited.
  template <class Visit>
  bool any_along(const Point& a, const Point& b, Visit&& visit) const {
    for (const int id : always_) {
      if (visit(id)) return true;
    }
    if (nodes_.empty()) return false;
    const Segment segment = segment_of(a, b);
    int stack[kMaxDepth];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[static_cast<std::size_t>(stack[--top])];
      if (!meets(segment, node.box)) continue;
      if (node.count > 0) {
        for (int e = node.first; e < node.first + node.count; ++e) {
          const auto& [id, box] = entries_[static_cast<std::size_t>(e)];
          if (meets(segment, box) && visit(id)) return true;
        }
        continue;
      }
      stack[top++] = node.first;  // children: first and first + 1
      stack[top++] = node.first + 1;
    }
    return false;
  }

 private:
  struct Segment {
    Point origin, direction;  // the points origin + t direction, 0 <= t <= 1
  };
  struct Node {
    Box box;        // grown a little, so that rounding cannot lose a crossing
    int first = 0;  // a leaf's first entry, or an inner node's first child
    int count = 0;  // a leaf's entries (0: an inner node)
  };
  static constexpr int kLeafSize = 4;
  static constexpr int kMaxDepth = 128;  // stack bound: depth is about log2(entries / kLeafSize)

  static Segment segment_of(const Point& a, const Point& b) { return {a, b - a}; }
  // Whether the segment meets the box, or the arithmetic cannot tell (NaN): conservative.
  static bool meets(const Segment& segment, const Box& box);
  // Fills nodes_[node] (already made) with entries [first, first + count), reordering them;
  // an inner node's two children are made next to each other.
  void build(int node, int first, int count, int depth);

  std::vector<std::pair<int, Box>> entries_;  // reordered into the leaves
  std::vector<Node> nodes_;
  std::vector<int> always_;  // ids of boxes with a NaN coordinate
};

}  // namespace holefill::detail
