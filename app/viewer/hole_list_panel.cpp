#include "hole_list_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "background.h"
#include "disabled_reasons.h"
#include "hole_table.h"
#include "widgets.h"

namespace holefill::viewer {
namespace {

// The filters say what they do: list "only" the ticked kinds, and how many rows that leaves.
void hole_filters(HoleView& view, std::size_t shown, std::size_t total) {
  ImGui::TextDisabled("only");
  tooltip("Tick kinds of hole to list only those; with none ticked every hole is listed");
  ImGui::SameLine();
  ImGui::Checkbox("open", &view.only_open);
  tooltip("Tick to list only the holes still open (with any other ticked kind)");
  ImGui::SameLine();
  ImGui::Checkbox("filled", &view.only_filled);
  tooltip("Tick to list only the filled holes (with any other ticked kind)");
  ImGui::SameLine();
  ImGui::Checkbox("failed", &view.only_failed);
  tooltip("Tick to list only the holes whose fill failed or that stay open with a reason");
  ImGui::SameLine();
  ImGui::Checkbox("intersecting", &view.only_intersecting);
  tooltip("Tick to list only the holes whose patch intersects the mesh");
  const bool filtered =
      view.only_open || view.only_filled || view.only_failed || view.only_intersecting;
  if (filtered)
    ImGui::TextDisabled("listing %zu of %zu (untick all to list every hole)", shown, total);
}

// Reads the table's sort order (a click on a header) into the view.
void take_sort_order(HoleView& view) {
  ImGuiTableSortSpecs* specs = ImGui::TableGetSortSpecs();
  if (!specs || !specs->SpecsDirty || specs->SpecsCount == 0) return;
  view.column = static_cast<HoleColumn>(specs->Specs[0].ColumnUserID);
  view.descending = specs->Specs[0].SortDirection == ImGuiSortDirection_Descending;
  specs->SpecsDirty = false;
}

// Why a hole failed or stays open, or that it is a border; empty for a plain hole.
std::string why_open(const Session& session, const HoleRow& row) {
  if (!row.failure.empty()) {
    return "Hole " + std::to_string(row.id) + ": " + row.failure +
           (row.remedy.empty() ? "" : "; " + row.remedy);
  }
  if (session.is_border(row.id) && row.status == HoleStatus::Open)
    return "Loop " + std::to_string(row.id) +
           " looks like the border of an open surface: Fill all leaves it, Fill closes it";
  return {};
}

// What hovering a row explains: why it failed or stays open, that it is a border.
void row_tooltip(const Session& session, const HoleRow& row) {
  if (!ImGui::IsItemHovered()) return;
  const std::string why = why_open(session, row);
  if (!why.empty()) wrapped_tooltip(why.c_str());
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

// A thin bar under the list: dragging it makes the list taller or shorter.
void resize_grip(UiState& ui, float height) {
  const float width = ImGui::GetContentRegionAvail().x;
  const ImVec2 at = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("##list_grip", ImVec2(width, scaled(6.0f)));
  const bool active = ImGui::IsItemActive(), hovered = ImGui::IsItemHovered();
  if (active || hovered) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeNS);
  if (active) ui.hole_list_height = std::max(height + ImGui::GetIO().MouseDelta.y, 1.0f);
  ImGui::GetWindowDrawList()->AddLine(
      ImVec2(at.x + 0.4f * width, at.y + scaled(3.0f)),
      ImVec2(at.x + 0.6f * width, at.y + scaled(3.0f)),
      ImGui::GetColorU32(active || hovered ? ImGuiCol_SeparatorActive : ImGuiCol_Separator), 2.0f);
  tooltip("Drag to make the list taller or shorter");
}

void hole_table(Session& session, UiState& ui, const std::vector<HoleRow>& rows) {
  // The list follows a hole picked in the 3D view.
  const bool follow = session.selected() != ui.listed_selection;
  ui.listed_selection = session.selected();
  // As tall as the rows up to 12 of them (or as the user dragged it), at least 3.
  const float row = ImGui::GetTextLineHeightWithSpacing();
  const float needed = static_cast<float>(rows.size() + 1) * row + scaled(6.0f);
  const float fits = std::min(needed, 13.0f * row + scaled(6.0f));
  const float height =
      std::max(ui.hole_list_height > 0.0f ? ui.hole_list_height : fits, 4.0f * row + scaled(6.0f));
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
  // The stage column takes the most of the width the numbers leave: "triangulated" reached the
  // table's edge when a scroll bar took its share (and the perimeter's header needs its own).
  ImGui::TableSetupColumn(
      "perimeter", ImGuiTableColumnFlags_PreferSortDescending | ImGuiTableColumnFlags_WidthStretch,
      1.4f, static_cast<ImGuiID>(HoleColumn::Perimeter));
  ImGui::TableSetupColumn(
      "area", ImGuiTableColumnFlags_PreferSortDescending | ImGuiTableColumnFlags_WidthStretch,
      0.85f, static_cast<ImGuiID>(HoleColumn::Area));
  ImGui::TableSetupColumn("stage", ImGuiTableColumnFlags_WidthStretch, 1.5f,
                          static_cast<ImGuiID>(HoleColumn::Status));
  ImGui::TableHeadersRow();
  take_sort_order(ui.holes);
  for (const auto& hole : rows) hole_row(session, hole, follow && hole.id == session.selected());
  ImGui::EndTable();
  resize_grip(ui, height);
}

// "Hole 0 with islands 3, 4": what one patch will close (or closed) with the selected hole, and
// why the selected hole failed or stays open, wrapped.
void selection_line(const Session& session, const std::vector<HoleRow>& all) {
  if (session.selected() < 0) return;
  const std::string why = why_open(session, all.at(session.selected()));
  if (!why.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, all.at(session.selected()).failure.empty()
                                             ? color(palette::kBorder)
                                             : kErrorColor);
    ImGui::TextWrapped("%s", why.c_str());
    ImGui::PopStyleColor();
  }
  if (const std::string features = feature_summary(session.selected_features());
      !features.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, color(palette::kFeatureLine));
    ImGui::TextWrapped("%s", features.c_str());
    ImGui::PopStyleColor();
  }
  if (session.joined().empty()) return;
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

void draw_hole_list(Session& session, const FileActions& files, Worker& worker, UiState& ui) {
  ImGui::Text("%s: %zu holes", files.file_name().c_str(), session.holes().size());
  const auto all = hole_rows(session);
  const auto rows = arrange(all, ui.holes);
  hole_filters(ui.holes, rows.size(), all.size());
  hole_table(session, ui, rows);
  if (rows.empty()) ImGui::TextDisabled("No hole matches the filters.");
  selection_line(session, all);
  const std::string why_not = why_not_frame(session);
  ImGui::BeginDisabled(!why_not.empty());
  if (ImGui::Button("Frame this hole")) ui.frame_selected = true;
  ImGui::EndDisabled();
  tooltip("Turn and zoom the view onto the selected hole (F)", why_not);
  ImGui::SameLine();
  if (ImGui::Button("Fit view")) ui.fit_view = true;
  tooltip("Show the whole mesh");
  ImGui::SameLine();
  if (ImGui::Button("Reset view")) ui.reset_view = true;
  tooltip("Back to the view the mesh opened with (R)");
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
