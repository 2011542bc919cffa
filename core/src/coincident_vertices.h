// Two different vertices of a loop at exactly one position: a zero-width crack or an unwelded
// seam, which no patch can cover but with triangles of zero width (triangulate_hole.cpp refuses
// such a loop; prepare.cpp keeps only the welds that leave none).
#pragma once

#include <optional>
#include <utility>

#include "holefill/holes.h"

namespace holefill::detail {

// The indices of two such vertices (the lower first), if any.
std::optional<std::pair<int, int>> coincident_vertices(const Mesh& mesh, const Hole& hole);

}  // namespace holefill::detail
