// The ImGui side panel: Open, Save, Save As, the hole list, fill options, the stage buttons,
// undo/redo, patch statistics with valence histograms, the comparison, display toggles, the
// screenshot button and the threads the work runs on, over a status bar of fixed height at the
// bottom (the last message, with its history) so that no message moves a control. It calls the
// session for every action and leaves requests that need the camera or the framebuffer (frame, fit,
// screenshot) in UiState for the frame loop.
#pragma once

#include <optional>
#include <string>

#include "display.h"
#include "file_actions.h"
#include "hole_table.h"
#include "notice_log.h"
#include "session.h"
#include "ui_scale.h"
#include "worker.h"

namespace holefill::viewer {

struct UiState {
  DisplayOptions display;
  std::string screenshot_path = "holefill-screenshot.png";
  // Requests the frame loop carries out and clears.
  bool frame_selected = false;
  bool fit_view = false;
  bool reset_view = false;
  bool take_screenshot = false;
  bool show_help = false;
  // The options while a slider is dragged (applied where it is let go), and while the worker
  // applies them.
  std::optional<FillOptions> dragged_options;
  std::optional<FillOptions> applying_options;
  int fill_all_max_edges = 0;     // "Fill holes up to N edges"; 0: all
  HoleView holes;                 // the hole list's order and filters
  int listed_selection = -1;      // the selection the list last showed (it scrolls to a new one)
  bool log_valences = false;      // valence charts on a log scale
  int compared_hole = -1;         // the hole the comparison showed last frame (framed when new)
  float content_scale = 1.0f;     // the monitor's (or --ui-scale)
  UiZoom zoom;                    // Ctrl +, Ctrl -, Ctrl 0
  UiScale scale;                  // what the panel is drawn at: ui_scale(content_scale, zoom)
  NoticeLog notices;              // the status bar's history
  float hole_list_height = 0.0f;  // pixels, once the user drags the list's grip; 0: as needed
};

// Fills run on `worker`; while it is busy the controls that change the session are disabled.
void draw_panels(Session& session, FileActions& files, Worker& worker, UiState& ui,
                 float window_height);

// While the comparison shows: each half's name and result at the top of the 3D view (from x =
// `left` to `right`, below `top`).
void draw_comparison_labels(Session& session, float left, float right, float top);

}  // namespace holefill::viewer
