// Dear ImGui at a UiScale (ui_scale.h): its default font rasterised at the scale's size, so that
// text stays crisp, and the dark style's paddings and roundings scaled with it.
#pragma once

#include "ui_scale.h"

namespace holefill::viewer {

// Call after ImGui_ImplOpenGL3_Init and outside a frame (before NewFrame): the font atlas and
// the OpenGL backend's font texture are made again.
void apply_ui_scale(const UiScale& scale);

}  // namespace holefill::viewer
