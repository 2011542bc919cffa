#include "valence_bins.h"

#include <algorithm>
#include <cmath>

namespace holefill::viewer {

std::array<ValenceBin, kValenceBins> valence_bins(const std::map<int, std::size_t>& histogram) {
  std::array<ValenceBin, kValenceBins> bins{
      {{"<=2"}, {"3"}, {"4"}, {"5"}, {"6"}, {"7"}, {"8"}, {"9"}, {">=10"}}};
  for (const auto& [valence, count] : histogram)
    bins[static_cast<std::size_t>(std::clamp(valence - 2, 0, 8))].count += count;
  return bins;
}

double bar_height(std::size_t count, std::size_t most, bool log) {
  if (most == 0) return 0.0;
  if (log) return std::log1p(static_cast<double>(count)) / std::log1p(static_cast<double>(most));
  return static_cast<double>(count) / static_cast<double>(most);
}

std::array<std::optional<float>, kValenceBins> label_positions(
    const std::array<float, kValenceBins>& widths, float width, float gap) {
  const float slot = width / static_cast<float>(kValenceBins);
  std::array<std::optional<float>, kValenceBins> positions;
  // Every label, else every other, every fourth, the two ends: strides that keep both ends.
  for (const std::size_t stride : {1u, 2u, 4u, 8u}) {
    positions = {};
    float previous_end = -gap;
    bool apart = true;
    for (std::size_t i = 0; i < kValenceBins; i += stride) {
      const float centred = slot * (static_cast<float>(i) + 0.5f) - 0.5f * widths[i];
      positions[i] = std::clamp(centred, 0.0f, std::max(0.0f, width - widths[i]));
      apart = apart && *positions[i] >= previous_end + gap;
      previous_end = *positions[i] + widths[i];
    }
    if (apart) break;
  }
  return positions;
}

}  // namespace holefill::viewer
