// The side panel's hole list: a sortable, filterable table of every loop (click selects,
// shift-click adds a loop to the selection or takes it out), what the selected hole closes with
// it, the view buttons and Bridge (two selected loops joined by one band).
#pragma once

#include "panels.h"
#include "session.h"
#include "worker.h"

namespace holefill::viewer {

// The Bridge button starts its fill on `worker`.
void draw_hole_list(Session& session, Worker& worker, UiState& ui);

}  // namespace holefill::viewer
