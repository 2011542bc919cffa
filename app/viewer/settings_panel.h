// The panel's last row, about how the work runs rather than a fill: how many threads the worker
// opens, prepares and fills on (Session::set_threads), and, when the mesh has lone triangles or
// small pieces beside its surface, "Remove small pieces". ImGui.
#pragma once

#include "file_actions.h"
#include "session.h"
#include "worker.h"

namespace holefill::viewer {

// "threads": a slider from 0 (every core this process may run on, the default) to the cores
// (further when the command line gave more). Greyed out while the worker runs: its job reads
// the count.
void threads_setting(Session& session, const Worker& worker);

// "Remove small pieces", shown when the preparation found some (Session::pieces): opens the file
// again on the worker without the pieces of at most pieces().largest_small_piece faces (the
// command line's --remove-small-components). Greyed out, saying why, while a hole is filled
// (the fills would be lost) or the mesh came from no file.
void remove_pieces_button(Session& session, FileActions& files, Worker& worker);

}  // namespace holefill::viewer
