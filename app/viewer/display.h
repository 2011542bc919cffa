// How the scene is drawn: choices the panels change and the renderer reads (the panel's width:
// ui_scale.h).
#pragma once

namespace holefill::viewer {

struct DisplayOptions {
  bool wireframe = true;
  bool flat = false;
  bool patch_vertices = true;
  bool feature_lines = true;  // the selected hole's sharp features and their continuations
};

}  // namespace holefill::viewer
