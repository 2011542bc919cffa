#include "status_bar.h"

#include <imgui.h>

#include "widgets.h"

namespace holefill::viewer {
namespace {

float message_height() {
  return 2.0f * ImGui::GetFrameHeightWithSpacing() - ImGui::GetStyle().ItemSpacing.y;
}

void message(const Notice& notice) {
  if (notice.error) ImGui::PushStyleColor(ImGuiCol_Text, kErrorColor);
  ImGui::TextWrapped("%s", notice.text.c_str());
  if (notice.error) ImGui::PopStyleColor();
}

void history(const NoticeLog& notices) {
  if (!ImGui::BeginPopup("##history")) return;
  ImGui::TextDisabled("Messages, newest last");
  ImGui::BeginChild("##entries", ImVec2(scaled(420.0f), scaled(260.0f)), true);
  for (const auto& notice : notices.entries()) {
    message(notice);
    ImGui::Separator();
  }
  if (ImGui::IsWindowAppearing()) ImGui::SetScrollHereY(1.0f);
  ImGui::EndChild();
  ImGui::EndPopup();
}

}  // namespace

float status_bar_height() {
  return message_height() + 2.0f * ImGui::GetStyle().ItemSpacing.y + 1.0f;
}

void draw_status_bar(Session& session, NoticeLog& notices) {
  notices.observe(session.notice());
  ImGui::Separator();
  const Notice& notice = session.notice();
  const ImGuiStyle& style = ImGui::GetStyle();
  const float buttons = ImGui::CalcTextSize("History").x + 2.0f * style.FramePadding.x;
  ImGui::BeginChild("##status", ImVec2(-buttons - style.ItemSpacing.x, message_height()));
  if (notice.text.empty())
    ImGui::TextDisabled("No message.");
  else
    message(notice);
  ImGui::EndChild();
  ImGui::SameLine();
  ImGui::BeginGroup();
  ImGui::BeginDisabled(notices.entries().empty());
  if (ImGui::Button("History", ImVec2(buttons, 0.0f))) ImGui::OpenPopup("##history");
  ImGui::EndDisabled();
  tooltip("Every message since the viewer started",
          notices.entries().empty() ? "No message yet" : "");
  ImGui::BeginDisabled(notice.text.empty());
  if (ImGui::Button("Clear", ImVec2(buttons, 0.0f))) session.clear_notice();
  ImGui::EndDisabled();
  tooltip("Clear the message (History keeps it)");
  ImGui::EndGroup();
  history(notices);
}

}  // namespace holefill::viewer
