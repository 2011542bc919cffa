// How the scene is drawn: choices the panels change and the renderer reads (the panel's width:
// ui_scale.h).
#pragma once

namespace holefill::viewer {

struct DisplayOptions {
  bool wireframe = true;
  bool flat = false;
  bool patch_vertices = true;
};

}  // namespace holefill::viewer
