// Which of a mesh's holes fill_holes (fill.h) takes, and which it joins by a bridge: the part of a
// fill's request that names holes rather than how to fill them (FillOptions).
#pragma once

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "holefill/holes.h"

namespace holefill {

// The listed ids (all when empty), and only those with at most max_boundary_edges boundary edges
// (no limit when 0). fill_holes takes a hole with its islands and the hole bridged to it (the limit
// then applies to their edges together; listing any one of them takes them all).
struct HoleSelection {
  std::vector<int> hole_ids;
  std::size_t max_boundary_edges = 0;
  std::vector<std::pair<int, int>> bridges = {};  // pairs of holes joined by one band (bridge.h)

  // Whether `hole` on its own is listed and within the edge limit.
  bool includes(const Hole& hole) const {
    if (max_boundary_edges && hole.size() > max_boundary_edges) return false;
    return hole_ids.empty() ||
           std::find(hole_ids.begin(), hole_ids.end(), hole.id) != hole_ids.end();
  }
};

}  // namespace holefill
