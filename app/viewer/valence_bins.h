// The valence histogram's bins, the same for every chart (patch, mesh, both sides of the
// comparison) so they can be read side by side: "<=2", one bin per valence 3 to 9, and ">=10".
// No GL.
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <string>

namespace holefill::viewer {

struct ValenceBin {
  const char* label;
  std::size_t count = 0;
};

inline constexpr std::size_t kValenceBins = 9;

// Counts of `histogram` (valence -> vertices) in the fixed bins; outliers fall in the end bins.
std::array<ValenceBin, kValenceBins> valence_bins(const std::map<int, std::size_t>& histogram);

// A bar's height as a share of the chart (0 to 1) for `count` when the tallest is `most`; with
// `log`, heights follow log(1 + count) so that small bins of a big mesh stay visible.
double bar_height(std::size_t count, std::size_t most, bool log);

// Where each bin's label goes under a chart `width` wide (x from its left edge), given the
// labels' widths: centred under its bar but within the chart. Where they would come closer
// than `gap` (the comparison's half-width charts), every other label, else every fourth, else
// the two ends. Nothing for a label left out.
std::array<std::optional<float>, kValenceBins> label_positions(
    const std::array<float, kValenceBins>& widths, float width, float gap);

}  // namespace holefill::viewer
