#include "settings_panel.h"

#include <algorithm>
#include <string>

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

}  // namespace holefill::viewer
