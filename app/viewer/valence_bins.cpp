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

}  // namespace holefill::viewer
