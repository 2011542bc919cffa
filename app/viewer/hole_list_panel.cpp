#include "hole_list_panel.h"

#include <imgui.h>

#include <cstdio>
#include <string>

#include "background.h"
#include "hole_table.h"
#include "widgets.h"

namespace holefill::viewer {
namespace {

void hole_filters(HoleView& view) {
  ImGui::TextDisabled("show");
  ImGui::SameLine();
  ImGui::Checkbox("open", &view.only_open);
  ImGui::SameLine();
  ImGui::Checkbox("filled", &view.only_filled);
  ImGui::SameLine();
  ImGui::Checkbox("failed", &view.only_failed);
  ImGui::SameLine();
  ImGui::Checkbox("intersecting", &view.only_intersecting);
  tooltip("Show only the holes with any of the ticked states (none ticked: all)");
}

// Reads the table's sort order (a click on a header) into the view.
void take_sort_order(HoleView& view) {
  ImGuiTableSortSpecs* specs = ImGui::TableGetSortSpecs();
  if (!specs || !specs->SpecsDirty || specs->SpecsCount == 0) return;
  view.column = static_cast<HoleColumn>(specs->Specs[0].ColumnUserID);
  view.descending = specs->Specs[0].SortDirection == ImGuiSortDirection_Descending;
  specs->SpecsDirty = false;
}

// What hovering a row explains: why it failed or stays open, that it is a border.
void row_tooltip(const Session& session, const HoleRow& row) {
  if (!ImGui::IsItemHovered()) return;
  if (!row.failure.empty()) {
    ImGui::SetTooltip("Hole %d: %s", row.id, row.failure.c_str());
  } else if (session.is_border(row.id)) {
    ImGui::SetTooltip(
        "Loop %d looks like the border of an open surface: Fill all leaves it, Fill closes it",
        row.id);
  }
}

void hole_row(Session& session, const HoleRow& row, bool scroll_here) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  // A border's id in the border colour (as in the 3D view), so no label needs the room.
  const bool border = session.is_border(row.id);
  if (border) ImGui::PushStyleColor(ImGuiCol_Text, color(palette::kBorder));
  const std::string label = std::to_string(row.id);
  if (ImGui::Selectable(label.c_str(), session.in_selection(row.id),
                        ImGuiSelectableFlags_SpanAllColumns)) {
    if (ImGui::GetIO().KeyShift)
      session.toggle(row.id);
    else
      session.select(row.id);
  }
  if (border) ImGui::PopStyleColor();
  if (scroll_here) ImGui::SetScrollHereY();
  row_tooltip(session, row);
  ImGui::TableNextColumn();
  ImGui::Text("%zu", row.edges);
  ImGui::TableNextColumn();
  ImGui::Text("%.4g", row.perimeter);
  ImGui::TableNextColumn();
  ImGui::Text("%.4g", row.area);
  ImGui::TableNextColumn();
  const bool failed = row.status == HoleStatus::Failed;
  if (failed) ImGui::PushStyleColor(ImGuiCol_Text, kErrorColor);
  const char* stage = border && row.status == HoleStatus::Open ? "border" : row.stage.c_str();
  ImGui::Text("%s%s%s", stage, row.intersecting ? " (x)" : "", row.failure.empty() ? "" : " (!)");
  if (failed) ImGui::PopStyleColor();
}

void hole_table(Session& session, UiState& ui, const std::vector<HoleRow>& rows) {
  // The list follows a hole picked in the 3D view.
  const bool follow = session.selected() != ui.listed_selection;
  ui.listed_selection = session.selected();
  const float height = 5.0f * ImGui::GetTextLineHeightWithSpacing() + scaled(6.0f);
  if (!ImGui::BeginTable("holes", 5,
                         ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY |
                             ImGuiTableFlags_BordersOuter | ImGuiTableFlags_Sortable,
                         ImVec2(0.0f, height))) {
    return;
  }
  ImGui::TableSetupScrollFreeze(0, 1);
  ImGui::TableSetupColumn("hole",
                          ImGuiTableColumnFlags_DefaultSort | ImGuiTableColumnFlags_WidthFixed,
                          scaled(40.0f), static_cast<ImGuiID>(HoleColumn::Id));
  ImGui::TableSetupColumn(
      "edges", ImGuiTableColumnFlags_PreferSortDescending | ImGuiTableColumnFlags_WidthFixed,
      scaled(48.0f), static_cast<ImGuiID>(HoleColumn::Edges));
  ImGui::TableSetupColumn("perimeter", ImGuiTableColumnFlags_PreferSortDescending, 0.0f,
                          static_cast<ImGuiID>(HoleColumn::Perimeter));
  ImGui::TableSetupColumn("area", ImGuiTableColumnFlags_PreferSortDescending, 0.0f,
                          static_cast<ImGuiID>(HoleColumn::Area));
  ImGui::TableSetupColumn("stage", 0, 0.0f, static_cast<ImGuiID>(HoleColumn::Status));
  ImGui::TableHeadersRow();
  take_sort_order(ui.holes);
  for (const auto& row : rows) hole_row(session, row, follow && row.id == session.selected());
  ImGui::EndTable();
}

// "Hole 0 with islands 3, 4": what one patch will close (or closed) with the selected hole.
void selection_line(const Session& session) {
  if (session.selected() < 0 || session.joined().empty()) return;
  std::string loops;
  for (const int id : session.joined()) {
    loops += ' ';
    loops += std::to_string(id);
  }
  ImGui::PushStyleColor(ImGuiCol_Text, color(palette::kJoinedBoundary));
  ImGui::TextWrapped("One patch: hole %d + loop%s%s (shift-click to change)", session.selected(),
                     session.joined().size() > 1 ? "s" : "", loops.c_str());
  ImGui::PopStyleColor();
}

}  // namespace

void draw_hole_list(Session& session, Worker& worker, UiState& ui) {
  ImGui::Text("%s: %zu holes", session.name().c_str(), session.holes().size());
  hole_filters(ui.holes);
  const auto rows = arrange(hole_rows(session), ui.holes);
  hole_table(session, ui, rows);
  if (rows.empty()) ImGui::TextDisabled("No hole matches the filters.");
  selection_line(session);
  ImGui::BeginDisabled(session.selected() < 0);
  if (ImGui::Button("Frame this hole")) ui.frame_selected = true;
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button("Fit view")) ui.fit_view = true;
  ImGui::SameLine();
  if (ImGui::Button("Reset view")) ui.reset_view = true;
  ImGui::SameLine();
  ImGui::BeginDisabled(worker.busy() || !session.bridge_problem().empty());
  if (ImGui::Button("Bridge")) start_fill(worker, session, session.fill_selected_request());
  ImGui::EndDisabled();
  tooltip(session.bridge_problem().empty()
              ? "Close the gap between the two selected loops with one band, then refine and "
                "smooth it"
              : session.bridge_problem().c_str());
}

}  // namespace holefill::viewer
