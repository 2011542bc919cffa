// The session's long operations as Worker jobs: fills computed on a copy and applied when done,
// undo, redo, reset and option changes rebuilt the same way, and opening a mesh into a new
// session that replaces the current one when it is read. No GL.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "file_actions.h"
#include "session.h"
#include "worker.h"

namespace holefill::viewer {

// Starts `request` (from Session's *_request) on the worker; false when there is nothing to do
// or the worker is busy. While it runs the caller must not step, undo, reset or change options.
bool start_fill(Worker& worker, Session& session, const std::optional<FillRequest>& request);

// Starts `change` (from Session's undo_request, redo_request, reset_request, options_request);
// false when there is nothing to do or the worker is busy. The same rule holds while it runs.
bool start_change(Worker& worker, Session& session, const std::optional<LogChange>& change);

// Sets the session's options: at once when no filled hole is selected, else by re-running that
// hole's steps on the worker. False when the worker is busy (nothing changes).
bool start_options(Worker& worker, Session& session, const FillOptions& options);

// Starts making the comparison the session asks for (Session::comparison_request); false when
// none is asked for or the worker is busy.
bool start_comparison(Worker& worker, Session& session);

// Starts reading `path` into a new session (on session's threads, without the pieces of at most
// `remove_pieces_up_to` faces: Session::open); when done it replaces `session` and tells `files`
// (opened), or, when the file cannot be read, leaves the session and shows why (notice).
bool start_open(Worker& worker, Session& session, FileActions& files,
                const std::filesystem::path& path, std::size_t remove_pieces_up_to = 0);
// Whether the worker is opening a mesh (start_open).
bool opening(const Worker& worker);
// What the status bar says once the worker's job is cancelled: "Filling hole 3: cancelled, mesh
// unchanged", "Opening scan.ply: cancelled".
std::string cancelled_notice(const Worker& worker);

}  // namespace holefill::viewer
