// How the window is laid out and the scene drawn: choices the panels change and the renderer
// reads.
#pragma once

namespace holefill::viewer {

// The side panel's width in window pixels; the 3D view takes the rest of the window.
constexpr float kPanelWidth = 390.0f;

struct DisplayOptions {
  bool wireframe = true;
  bool flat = false;
  bool patch_vertices = true;
};

}  // namespace holefill::viewer
