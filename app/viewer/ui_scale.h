// How big the panel's text and widgets are drawn: the monitor's content scale (a HiDPI screen
// asks for 1.5 or 2) times the user's zoom, Ctrl +, Ctrl − and Ctrl 0 moving along a ladder of
// factors as a browser does. The font is rasterised at a whole number of pixels (crisp), and the
// panel's widths follow the font. No GL and no ImGui.
#pragma once

#include "shortcuts.h"

namespace holefill::viewer {

// ImGui's default font's size, in pixels, at scale 1: the panel's widths are written for it.
constexpr int kBaseFontPixels = 13;

// The side panel's width at scale 1; the 3D view takes the rest of the window.
constexpr float kPanelWidth = 390.0f;

struct UiScale {
  int font_pixels = kBaseFontPixels;
  float factor = 1.0f;  // font_pixels / kBaseFontPixels: what every width is multiplied by
  // In window pixels.
  float panel_width() const { return kPanelWidth * factor; }
  bool operator==(const UiScale&) const = default;
};

// The user's zoom: an index on the ladder of factors, 0 being 100 %.
struct UiZoom {
  int level = 0;
};

// The scale for a monitor's `content_scale` (glfwGetWindowContentScale; taken as 1 when not
// positive) at `zoom`: the font at the nearest whole pixel size to 13 px times both, kept
// within 8 to 48 px.
UiScale ui_scale(float content_scale, UiZoom zoom);

// The zoom after `command`: ZoomIn and ZoomOut move one rung (not past either end), ZoomReset
// goes back to 100 %; any other command leaves it.
UiZoom zoom_after(UiZoom zoom, Command command);

// The zoom's factor (1 at 100 %), for showing it.
float zoom_factor(UiZoom zoom);

}  // namespace holefill::viewer
