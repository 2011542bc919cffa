// The session's long operations as Worker jobs: fills computed on a copy and applied when done,
// and opening a mesh into a new session that replaces the current one when it is read. No GL.
#pragma once

#include <filesystem>
#include <optional>

#include "file_actions.h"
#include "session.h"
#include "worker.h"

namespace holefill::viewer {

// Starts `request` (from Session's *_request) on the worker; false when there is nothing to do
// or the worker is busy. While it runs the caller must not step, undo, reset or change options.
bool start_fill(Worker& worker, Session& session, const std::optional<FillRequest>& request);

// Starts reading `path` into a new session; when done it replaces `session` and tells `files`
// (opened), or, when the file cannot be read, leaves the session and shows why (notice).
bool start_open(Worker& worker, Session& session, FileActions& files,
                const std::filesystem::path& path);

}  // namespace holefill::viewer
