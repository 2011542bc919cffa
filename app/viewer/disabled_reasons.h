// Why a greyed-out button of the panel cannot be used now, in words for its tooltip (issue 31):
// each function returns an empty string when the action is possible. No GL.
#pragma once

#include <cstddef>
#include <string>

#include "holefill/patch.h"
#include "session.h"

namespace holefill::viewer {

// Triangulate, Refine, Smooth on the selected hole.
std::string why_not_step(const Session& session, Stage stage);
// Fill: the selected hole's remaining stages.
std::string why_not_fill_selected(const Session& session);
// Reset hole.
std::string why_not_reset(const Session& session);
// Fill all holes (up to `max_edges` boundary edges; 0: any).
std::string why_not_fill_all(const Session& session, std::size_t max_edges);
std::string why_not_undo(const Session& session);
std::string why_not_redo(const Session& session);
// Frame this hole.
std::string why_not_frame(const Session& session);

// What every button that changes the mesh says while the worker runs.
inline constexpr const char* kBusyReason =
    "Busy: wait for the work in progress to end, or press Esc to cancel it";

}  // namespace holefill::viewer
