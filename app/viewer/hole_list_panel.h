// The side panel's hole list: a sortable, filterable table of every loop (click selects,
// shift-click adds a loop to the selection or takes it out), what the selected hole closes with
// it (and why it stays open, when it does), the view buttons and Bridge (two selected loops
// joined by one band). The list is as tall as its rows up to a limit; a grip under it resizes it.
#pragma once

#include "file_actions.h"
#include "panels.h"
#include "session.h"
#include "worker.h"

namespace holefill::viewer {

// The Bridge button starts its fill on `worker`; the heading names the file `files` works on.
void draw_hole_list(Session& session, const FileActions& files, Worker& worker, UiState& ui);

}  // namespace holefill::viewer
