#include "ui_scale.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace holefill::viewer {
namespace {

// The rungs below and above 100 %, as browsers and editors offer them.
constexpr float kLadder[] = {0.6f,  0.7f, 0.8f,  0.9f, 1.0f, 1.1f,
                             1.25f, 1.5f, 1.75f, 2.0f, 2.5f, 3.0f};
constexpr int kUnitRung = 4;
constexpr int kMinFontPixels = 8;
constexpr int kMaxFontPixels = 48;

int rung_of(UiZoom zoom) {
  return std::clamp(kUnitRung + zoom.level, 0, static_cast<int>(std::size(kLadder)) - 1);
}

}  // namespace

float zoom_factor(UiZoom zoom) { return kLadder[rung_of(zoom)]; }

UiScale ui_scale(float content_scale, UiZoom zoom) {
  const float monitor = content_scale > 0.0f ? content_scale : 1.0f;
  const float wanted = static_cast<float>(kBaseFontPixels) * monitor * zoom_factor(zoom);
  const int pixels =
      std::clamp(static_cast<int>(std::lround(wanted)), kMinFontPixels, kMaxFontPixels);
  return {pixels, static_cast<float>(pixels) / static_cast<float>(kBaseFontPixels)};
}

UiZoom zoom_after(UiZoom zoom, Command command) {
  switch (command) {
    case Command::ZoomIn:
      return {rung_of({zoom.level + 1}) - kUnitRung};
    case Command::ZoomOut:
      return {rung_of({zoom.level - 1}) - kUnitRung};
    case Command::ZoomReset:
      return {};
    default:
      return zoom;
  }
}

}  // namespace holefill::viewer
