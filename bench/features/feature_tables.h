// The Markdown tables of holefill-features (README.md): cover per case and recipe with the sums,
// the crease inside the hole, and every measure.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "crease_measure.h"

namespace holefill::features {

// One case filled by one recipe, measured.
struct Row {
  std::string name, what, recipe;
  std::size_t hole_edges = 0;
  FeatureQuality quality;
  std::string notes;
};

// Prints the tables to std::cout, the recipes' columns in the order given.
void print_tables(const std::vector<Row>& rows, const std::vector<std::string>& recipes);

}  // namespace holefill::features
