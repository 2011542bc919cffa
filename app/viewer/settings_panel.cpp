#include "settings_panel.h"

#include <algorithm>
#include <string>

#include "background.h"
#include "holefill/cores.h"
#include "widgets.h"

namespace holefill::viewer {

// The default is every core: the worker and every thread it starts run at a lower priority than
// the window's thread (worker.cpp: nice 4, which threads inherit), so a fill that keeps every
// core busy still leaves the window its frames and Esc at once, and a fill on every core ends
// soonest. Fewer threads leave cores to other programs.
void threads_setting(Session& session, const Worker& worker) {
  const auto cores = static_cast<int>(available_cores());
  int threads = static_cast<int>(session.threads());
  const std::string every = "every core (" + std::to_string(cores) + ")";
  ImGui::BeginDisabled(worker.busy());
  ImGui::SetNextItemWidth(scaled(150.0f));
  if (ImGui::SliderInt("threads", &threads, 0, std::max(cores, threads),
                       threads == 0 ? every.c_str() : "%d", ImGuiSliderFlags_AlwaysClamp)) {
    session.set_threads(static_cast<unsigned>(threads));
  }
  ImGui::EndDisabled();
  tooltip(
      "Threads that open, prepare and fill meshes (0: every core this process may run on). "
      "They run below the window's priority, so the window stays responsive whatever the "
      "number; fewer leave cores to other programs. The result is the same whatever the number",
      worker.busy() ? "The work under way reads it: wait for it, or cancel it (Esc)" : "");
}

void remove_pieces_button(Session& session, FileActions& files, Worker& worker) {
  const PieceCounts& pieces = session.pieces();
  if (pieces.lone_triangles + pieces.small_pieces == 0) return;
  std::string why_not;
  if (files.opened_path().empty()) {
    why_not = "The mesh was read from no file";
  } else if (!session.log().empty()) {
    why_not = "Removing them opens the file again, without the fills: reset or undo them first";
  }
  ImGui::SameLine();
  ImGui::BeginDisabled(!why_not.empty() || worker.busy());
  if (ImGui::Button("Remove small pieces")) {
    start_open(worker, session, files, files.opened_path(), pieces.largest_small_piece);
  }
  ImGui::EndDisabled();
  const std::string what = "Open " + files.opened_path().filename().string() +
                           " again without the pieces of at most " +
                           std::to_string(pieces.largest_small_piece) +
                           " faces beside the surface (the largest piece is kept)";
  tooltip(what.c_str(), why_not);
}

}  // namespace holefill::viewer
