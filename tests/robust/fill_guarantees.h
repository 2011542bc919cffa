// The guarantees every fill must keep, checked on a mesh before and after: the
// original part unchanged bit for bit, only patch elements added, an oriented mesh no less
// manifold than before, each filled hole's loop gone and every other loop exactly as it was, and
// no degenerate patch triangle. Free of GoogleTest, so the fuzz targets use it too.
#pragma once

#include <string>
#include <vector>

#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/mesh.h"

namespace holefill::testing {

// The first guarantee `after` breaks, in words; empty when it keeps them all. `holes` are
// find_holes(before); `fills` what fill_holes (or fill_hole per hole, in order) returned.
std::string check_fill_guarantees(const Mesh& before, const std::vector<Hole>& holes,
                                  const Mesh& after, const std::vector<HoleFill>& fills);

// Each face has three distinct, valid corners and every directed edge is used by at most one
// face (the mesh is consistently oriented and edge-manifold); empty when so.
std::string check_oriented(const Mesh& mesh);

}  // namespace holefill::testing
