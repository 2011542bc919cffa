#include "disabled_reasons.h"

namespace holefill::viewer {
namespace {

const char* kNoSelection = "Select a hole first: click on or inside its outline, or in the list";

std::string hole(const Session& session) { return "Hole " + std::to_string(session.selected()); }

}  // namespace

std::string why_not_step(const Session& session, Stage stage) {
  if (session.selected() < 0) return kNoSelection;
  const HoleFill& fill = session.fill(session.selected());
  if (fill.failed())
    return hole(session) + " failed (" + fill.failure.message + "): Reset hole first";
  const auto next = session.next_stage();
  if (!next) return hole(session) + " is filled: every stage has run";
  if (*next == stage) return {};
  if (static_cast<int>(stage) < static_cast<int>(*next))
    return hole(session) + " is " + to_string(fill.stage()) + " already";
  return "Run the stages in order: " + std::string(to_string(*next)) + " comes first";
}

std::string why_not_fill_selected(const Session& session) {
  if (session.selected() < 0) return kNoSelection;
  const HoleFill& fill = session.fill(session.selected());
  if (fill.failed())
    return hole(session) + " failed (" + fill.failure.message + "): Reset hole first";
  if (!session.next_stage()) return hole(session) + " is filled: every stage has run";
  return {};
}

std::string why_not_reset(const Session& session) {
  if (session.selected() < 0) return kNoSelection;
  const HoleFill& fill = session.fill(session.selected());
  if (fill.stage() == Stage::Original && !fill.failed())
    return hole(session) + " has no patch to take out";
  return {};
}

std::string why_not_fill_all(const Session& session, std::size_t max_edges) {
  if (session.fill_all_request(max_edges)) return {};
  if (session.holes().empty()) return "The mesh has no holes";
  return max_edges > 0 ? "No open hole of at most " + std::to_string(max_edges) +
                             " edges is left (borders of open surfaces are filled one by one)"
                       : "No open hole is left (borders of open surfaces are filled one by one)";
}

std::string why_not_undo(const Session& session) {
  return session.can_undo() ? "" : "Nothing to undo";
}

std::string why_not_redo(const Session& session) {
  return session.can_redo() ? "" : "Nothing to redo";
}

std::string why_not_frame(const Session& session) {
  return session.selected() < 0 ? kNoSelection : "";
}

}  // namespace holefill::viewer
