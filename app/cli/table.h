// The tables `holefill` prints on standard output.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "holefill/fill.h"

namespace holefill::cli {

// `value` through a printf pattern with one double conversion, e.g. format("%.2f", x).
std::string format(const char* pattern, double value);

// "1,4,7".
std::string id_list(const std::vector<int>& ids);

// One row per hole fill: id, boundary, stage, new vertices and faces, quality, timing; the holes
// filled with it (its islands, the hole bridged to it) at the end of its row.
void print_fill_table(const std::vector<HoleFill>& fills, std::ostream& out);

}  // namespace holefill::cli
