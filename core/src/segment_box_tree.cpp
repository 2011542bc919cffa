#include "segment_box_tree.h"

#include <algorithm>
#include <cmath>

namespace holefill::detail {
namespace {

// Boxes are grown by this share of their coordinates' magnitude (and extent), far above the
// rounding of the crossing test and far below any feature a mesh resolves.
constexpr double kRelativeMargin = 1e-9;

bool has_nan(const Box& box) {
  for (int axis = 0; axis < 3; ++axis) {
    if (std::isnan(box.low[axis]) || std::isnan(box.high[axis])) return true;
  }
  return false;
}

Box grown_for_rounding(Box box) {
  const double extent = (box.high - box.low).max();
  const double margin =
      kRelativeMargin * std::max(box.magnitude(), std::isfinite(extent) ? extent : 0.0);
  box.grow(std::isfinite(margin) ? margin : 0.0);
  return box;
}

double box_centre(const Box& box, int axis) { return 0.5 * box.low[axis] + 0.5 * box.high[axis]; }

}  // namespace

SegmentBoxTree::SegmentBoxTree(std::vector<std::pair<int, Box>> boxes) {
  for (auto& [id, box] : boxes) {
    if (has_nan(box)) {
      always_.push_back(id);
    } else {
      entries_.emplace_back(id, grown_for_rounding(box));
    }
  }
  if (entries_.empty()) return;
  nodes_.reserve(2 * entries_.size() / kLeafSize + 2);
  nodes_.emplace_back();
  build(0, 0, static_cast<int>(entries_.size()), 0);
}

void SegmentBoxTree::build(int node, int first, int count, int depth) {
  Box box, centres;
  for (int e = first; e < first + count; ++e) {
    const Box& entry = entries_[static_cast<std::size_t>(e)].second;
    box.add(entry);
    centres.add(Point(box_centre(entry, 0), box_centre(entry, 1), box_centre(entry, 2)));
  }
  nodes_[static_cast<std::size_t>(node)].box = box;
  // A leaf also where the tree would get deeper than the stack of any_along holds.
  if (count <= kLeafSize || depth + 1 >= kMaxDepth / 2) {
    nodes_[static_cast<std::size_t>(node)].first = first;
    nodes_[static_cast<std::size_t>(node)].count = count;
    return;
  }
  // Split at the median centre along the axis the centres spread most on.
  const Point spread = centres.high - centres.low;
  int axis = 0;
  for (int a = 1; a < 3; ++a) {
    if (spread[a] > spread[axis]) axis = a;
  }
  const int half = count / 2;
  const auto begin = entries_.begin() + first;
  std::nth_element(begin, begin + half, begin + count, [axis](const auto& p, const auto& q) {
    return box_centre(p.second, axis) < box_centre(q.second, axis);
  });
  const int children = static_cast<int>(nodes_.size());
  nodes_[static_cast<std::size_t>(node)].first = children;
  nodes_.emplace_back();
  nodes_.emplace_back();
  build(children, first, half, depth + 1);
  build(children + 1, first + half, count - half, depth + 1);
}

bool SegmentBoxTree::meets(const Segment& segment, const Box& box) {
  // The parameters t in [0, 1] inside each slab, narrowed axis by axis. Comparisons are written
  // so that a NaN keeps the box (never a false "misses").
  double enter = 0.0, leave = 1.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double o = segment.origin[axis], d = segment.direction[axis];
    if (d == 0.0) {
      if (o < box.low[axis] || o > box.high[axis]) return false;
      continue;
    }
    double t0 = (box.low[axis] - o) / d, t1 = (box.high[axis] - o) / d;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > enter) enter = t0;
    if (t1 < leave) leave = t1;
    if (enter > leave) return false;
  }
  return true;
}

}  // namespace holefill::detail
