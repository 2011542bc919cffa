// Small ImGui helpers the side panel's sections share.
#pragma once

#include <imgui.h>

#include <string>

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

// A tooltip with `text` wrapped at a readable width (about 40 characters), so that it never runs
// past the window's edge.
inline void wrapped_tooltip(const char* text) {
  ImGui::BeginTooltip();
  ImGui::PushTextWrapPos(ImGui::GetFontSize() * 24.0f);
  ImGui::TextUnformatted(text);
  ImGui::PopTextWrapPos();
  ImGui::EndTooltip();
}

// The last item's tooltip, also while it is disabled (it then says why, or what it would do).
inline void tooltip(const char* text) {
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) wrapped_tooltip(text);
}
inline void tooltip(const std::string& text) { tooltip(text.c_str()); }

// The last item's tooltip: `enabled_text` while it can be used, else why not.
inline void tooltip(const char* enabled_text, const std::string& why_not) {
  tooltip(why_not.empty() ? std::string(enabled_text) : why_not);
}

}  // namespace holefill::viewer
