// Small ImGui helpers the side panel's sections share.
#pragma once

#include <imgui.h>

#include "palette.h"
#include "ui_scale.h"

namespace holefill::viewer {

inline const ImVec4 kErrorColor{1.0f, 0.45f, 0.4f, 1.0f};

inline ImVec4 color(const palette::Rgb& c) {
  return ImVec4(c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f, 1.0f);
}

// A size written for the 13 px font, at the current font's size (Ctrl +/-, the monitor's scale).
inline float scaled(float pixels) {
  return pixels * ImGui::GetFontSize() / static_cast<float>(kBaseFontPixels);
}

// The last item's tooltip, also while it is disabled (it then says why, or what it would do).
inline void tooltip(const char* text) {
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", text);
}

}  // namespace holefill::viewer
