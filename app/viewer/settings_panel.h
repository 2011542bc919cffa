// The panel's settings of the machine rather than of a fill: how many threads the worker opens,
// prepares and fills on (Session::set_threads). ImGui.
#pragma once

#include "session.h"
#include "worker.h"

namespace holefill::viewer {

// "threads": a slider from 0 (every core this process may run on, the default) to the cores
// (further when the command line gave more). Greyed out while the worker runs: its job reads
// the count.
void threads_setting(Session& session, const Worker& worker);

}  // namespace holefill::viewer
