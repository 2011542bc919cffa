#include "ui_style.h"

#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

namespace holefill::viewer {

void apply_ui_scale(const UiScale& scale) {
  ImFontAtlas& fonts = *ImGui::GetIO().Fonts;
  fonts.Clear();
  // ProggyClean, ImGui's own font, as AddFontDefault sets it up for 13 px (no oversampling,
  // snapped to pixels), at the scale's size.
  ImFontConfig config;
  config.SizePixels = static_cast<float>(scale.font_pixels);
  config.OversampleH = config.OversampleV = 1;
  config.PixelSnapH = true;
  fonts.AddFontDefault(&config);
  ImGuiStyle style;
  ImGui::StyleColorsDark(&style);
  style.ScaleAllSizes(scale.factor);
  ImGui::GetStyle() = style;
  ImGui_ImplOpenGL3_DestroyFontsTexture();
  ImGui_ImplOpenGL3_CreateFontsTexture();
}

}  // namespace holefill::viewer
