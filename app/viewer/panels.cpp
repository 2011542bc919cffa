#include "panels.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <utility>
#include <vector>

#include "background.h"
#include "palette.h"

namespace holefill::viewer {
namespace {

constexpr float kSqrt2 = 1.41421356f;
const ImVec4 kErrorColor{1.0f, 0.45f, 0.4f, 1.0f};

void histogram(const char* id, const std::map<int, std::size_t>& valences, float height) {
  if (valences.empty()) {
    ImGui::TextDisabled("(no vertices)");
    return;
  }
  const int first = std::min(3, valences.begin()->first);
  const int last = std::max(9, valences.rbegin()->first);
  std::vector<float> counts(static_cast<std::size_t>(last - first + 1), 0.0f);
  float most = 0.0f;
  for (const auto& [valence, count] : valences) {
    counts[static_cast<std::size_t>(valence - first)] = static_cast<float>(count);
    most = std::max(most, static_cast<float>(count));
  }
  char label[64];
  std::snprintf(label, sizeof label, "valence %d .. %d", first, last);
  ImGui::PlotHistogram(id, counts.data(), static_cast<int>(counts.size()), 0, label, 0.0f,
                       most * 1.1f, ImVec2(ImGui::GetContentRegionAvail().x, height));
}

void patch_statistics(const HoleFill& fill) {
  if (fill.failed()) {
    ImGui::TextColored(kErrorColor, "Failed: %s", fill.failure.c_str());
    return;
  }
  if (fill.stage() == Stage::Original) {
    ImGui::TextDisabled("Not filled yet.");
    return;
  }
  const PatchStats& s = fill.stats;
  ImGui::Text("Stage: %s", to_string(fill.stage()));
  ImGui::Text("New vertices %zu   new faces %zu", s.new_vertices, s.new_faces);
  ImGui::Text("Min angle %.2f deg (mean %.2f)", s.min_angle_deg, s.mean_min_angle_deg);
  ImGui::Text("Max dihedral %.2f deg   area %.4g", s.max_dihedral_deg, s.area);
  ImGui::Text("Times: tri %.1f  ref %.1f  smo %.1f ms", 1e3 * fill.times.triangulate_seconds,
              1e3 * fill.times.refine_seconds, 1e3 * fill.times.smooth_seconds);
  if (!fill.smoothing_note.empty()) ImGui::TextWrapped("%s", fill.smoothing_note.c_str());
}

void tooltip(const char* text) {
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", text);
}

void file_section(Session& session, FileActions& files, UiState& ui) {
  if (ImGui::Button("Open...")) files.open();
  tooltip("Open a mesh (Ctrl+O); or drop a file on the window");
  ImGui::SameLine();
  if (ImGui::Button("Save")) files.save();
  const std::string save_tip =
      files.save_target()
          ? "Save to " + files.save_target()->string() + " (Ctrl+S)"
          : std::string("Save the filled mesh: asks where, the first time (Ctrl+S)");
  tooltip(save_tip.c_str());
  ImGui::SameLine();
  if (ImGui::Button("Save As...")) files.save_as();
  tooltip("Save the filled mesh as OBJ, OFF, PLY or STL (Ctrl+Shift+S)");
  ImGui::SameLine();
  if (ImGui::Button("Keys (F1)")) ui.show_help = true;
  const Notice& notice = session.notice();
  if (!notice.text.empty()) {
    if (notice.error) ImGui::PushStyleColor(ImGuiCol_Text, kErrorColor);
    ImGui::TextWrapped("%s", notice.text.c_str());
    if (notice.error) ImGui::PopStyleColor();
    if (ImGui::SmallButton("Dismiss")) session.clear_notice();
  }
}

void hole_list(Session& session, UiState& ui) {
  ImGui::Text("%s: %zu holes", session.name().c_str(), session.holes().size());
  const float rows = static_cast<float>(std::min<std::size_t>(session.holes().size(), 6) + 1);
  if (ImGui::BeginTable(
          "holes", 4,
          ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_BordersOuter,
          ImVec2(0.0f, rows * ImGui::GetTextLineHeightWithSpacing() + 6.0f))) {
    ImGui::TableSetupScrollFreeze(0, 1);
    ImGui::TableSetupColumn("hole");
    ImGui::TableSetupColumn("edges");
    ImGui::TableSetupColumn("perimeter");
    ImGui::TableSetupColumn("stage");
    ImGui::TableHeadersRow();
    for (const auto& hole : session.holes()) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      char label[32];
      std::snprintf(label, sizeof label, "%d", hole.id);
      if (ImGui::Selectable(label, session.selected() == hole.id,
                            ImGuiSelectableFlags_SpanAllColumns)) {
        session.select(hole.id);
      }
      ImGui::TableNextColumn();
      ImGui::Text("%zu", hole.size());
      ImGui::TableNextColumn();
      ImGui::Text("%.4g", hole.perimeter);
      ImGui::TableNextColumn();
      const HoleFill& fill = session.fill(hole.id);
      ImGui::TextUnformatted(fill.failed() ? "failed" : to_string(fill.stage()));
    }
    ImGui::EndTable();
  }
  ImGui::BeginDisabled(session.selected() < 0);
  if (ImGui::Button("Frame this hole")) ui.frame_selected = true;
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button("Fit view")) ui.fit_view = true;
  ImGui::SameLine();
  if (ImGui::Button("Reset view")) ui.reset_view = true;
}

// What a slider did this frame: moved (show the value) and let go (apply it).
struct SliderEdit {
  bool moved = false;
  bool released = false;
  void after_item(bool changed) {
    moved = moved || changed;
    released = released || ImGui::IsItemDeactivatedAfterEdit();
  }
};

// The tau slider with a tick at sqrt(2), where Liepa's default sits.
bool tau_slider(float& tau, SliderEdit& edit) {
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - 70.0f);
  edit.after_item(ImGui::SliderFloat("##tau", &tau, 1.0f, 2.0f, "tau = %.3f"));
  tooltip(
      "Refinement density: a triangle is split while its edges are longer than tau times the "
      "boundary's scale. Smaller tau: denser patch. The tick is sqrt 2 (the paper's).");
  const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
  const float grab = ImGui::GetStyle().GrabMinSize;
  const float x = lo.x + grab * 0.5f + (kSqrt2 - 1.0f) * (hi.x - lo.x - grab);
  ImGui::GetWindowDrawList()->AddLine(ImVec2(x, lo.y), ImVec2(x, lo.y + 5.0f),
                                      IM_COL32(255, 220, 90, 255), 2.0f);
  ImGui::GetWindowDrawList()->AddLine(ImVec2(x, hi.y - 5.0f), ImVec2(x, hi.y),
                                      IM_COL32(255, 220, 90, 255), 2.0f);
  ImGui::SameLine();
  if (ImGui::Button("sqrt 2")) {
    tau = kSqrt2;
    return true;
  }
  return false;
}

// Combos, checkboxes and buttons apply at once; sliders show their value while dragged and
// apply it where the user lets go, so a drag re-runs the fill once, not at every step.
void options_section(Session& session, UiState& ui) {
  FillOptions options = ui.dragged_options.value_or(session.options());
  bool changed = false;
  SliderEdit slider;
  const WeightKind kinds[] = {WeightKind::MaxMin, WeightKind::Liepa, WeightKind::Area};
  ImGui::SetNextItemWidth(150.0f);
  if (ImGui::BeginCombo("weight", to_string(options.triangulate.weight).c_str())) {
    for (const auto kind : kinds) {
      if (ImGui::Selectable(to_string(kind).c_str(), kind == options.triangulate.weight)) {
        options.triangulate.weight = kind;
        changed = true;
      }
    }
    ImGui::EndCombo();
  }
  float tau = static_cast<float>(options.refine.tau);
  changed |= tau_slider(tau, slider);
  if (changed || slider.moved)
    options.refine.tau = std::abs(tau - kSqrt2) < 1e-6f ? std::sqrt(2.0) : tau;
  changed |= ImGui::Checkbox("remesh to valence 6", &options.refine.remesh);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "After refinement: valence-driven flips and tangential relaxation of the "
        "patch (not in the paper)");
  }
  // 0: umbrella; 1, 2: fairing of order 2 (bi-Laplacian) or 3 (tri-Laplacian).
  const bool fair = options.smooth.method == SmoothMethod::Fair;
  int method = fair ? options.smooth.fair.order - 1 : 0;
  ImGui::SetNextItemWidth(150.0f);
  if (ImGui::Combo("smoothing", &method, "umbrella (paper)\0fair (order 2)\0fair (order 3)\0")) {
    options.smooth.method = method > 0 ? SmoothMethod::Fair : SmoothMethod::Umbrella;
    if (method > 0) options.smooth.fair.order = method + 1;
    changed = true;
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "umbrella: the paper's Laplacian smoothing; fair: bi- (order 2) or tri-Laplacian "
        "(order 3) fairing that continues the surrounding curvature");
  }
  ImGui::BeginDisabled(fair);  // the umbrella operator's own settings
  ImGui::SetNextItemWidth(150.0f);
  slider.after_item(ImGui::SliderInt("smoothing iterations", &options.smooth.iterations, 0, 100));
  tooltip("Umbrella smoothing: how many times each new vertex moves toward its neighbours' mean");
  float step = static_cast<float>(options.smooth.step);
  ImGui::SetNextItemWidth(150.0f);
  const bool stepped = ImGui::SliderFloat("smoothing step", &step, 0.05f, 1.0f, "%.2f");
  slider.after_item(stepped);
  tooltip("Umbrella smoothing: the share of the way toward the mean each iteration moves");
  if (stepped) options.smooth.step = step;
  ImGui::EndDisabled();
  if (changed || slider.released) {
    ui.dragged_options.reset();
    session.set_options(options);
  } else if (slider.moved) {
    ui.dragged_options = options;
  }
}

void step_section(Session& session, Worker& worker, UiState& ui) {
  const auto stage_button = [&](const char* label, Stage stage) {
    ImGui::BeginDisabled(!session.can_step(stage));
    if (ImGui::Button(label)) start_fill(worker, session, session.step_request(stage));
    ImGui::EndDisabled();
  };
  stage_button("Triangulate", Stage::Triangulated);
  ImGui::SameLine();
  stage_button("Refine", Stage::Refined);
  ImGui::SameLine();
  stage_button("Smooth", Stage::Smoothed);
  ImGui::SameLine();
  ImGui::BeginDisabled(!session.next_stage());
  if (ImGui::Button("Fill")) start_fill(worker, session, session.fill_selected_request());
  ImGui::EndDisabled();
  tooltip("The selected hole's remaining stages (Shift+F)");
  ImGui::SameLine();
  const bool untouched =
      session.selected() < 0 || (session.fill(session.selected()).stage() == Stage::Original &&
                                 !session.fill(session.selected()).failed());
  ImGui::BeginDisabled(untouched);
  if (ImGui::Button("Reset hole")) session.reset_selected();
  tooltip("Take the selected hole's patch out again (Delete)");
  ImGui::EndDisabled();

  const auto limit = static_cast<std::size_t>(ui.fill_all_max_edges);
  ImGui::BeginDisabled(!session.fill_all_request(limit));
  if (ImGui::Button(limit ? "Fill holes up to" : "Fill all holes"))
    start_fill(worker, session, session.fill_all_request(limit));
  ImGui::EndDisabled();
  tooltip(
      "Every open hole's remaining stages, on a worker: Cancel leaves the mesh as it was "
      "(Ctrl+F)");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90.0f);
  if (ImGui::InputInt("edges##limit", &ui.fill_all_max_edges, 10, 100))
    ui.fill_all_max_edges = std::max(ui.fill_all_max_edges, 0);
  tooltip(
      "Fill only holes of at most this many boundary edges (0: every hole), like the "
      "command line's --max-boundary");
  ImGui::SameLine();
  ImGui::BeginDisabled(!session.can_undo());
  if (ImGui::Button("Undo")) session.undo();
  tooltip("Ctrl+Z");
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!session.can_redo());
  if (ImGui::Button("Redo")) session.redo();
  tooltip("Ctrl+Y or Ctrl+Shift+Z");
  ImGui::EndDisabled();
}

void statistics_section(Session& session) {
  if (session.selected() >= 0) {
    const HoleFill& fill = session.fill(session.selected());
    ImGui::Text("Hole %d patch", session.selected());
    patch_statistics(fill);
    ImGui::TextUnformatted("Valences of the patch's new vertices");
    histogram("##patch_valences", fill.stats.valence_histogram, 60.0f);
  } else {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped("Select a hole: click on or inside its outline, or in the list.");
    ImGui::PopStyleColor();
  }
  ImGui::Text("Valences of the whole mesh (%zu vertices)", session.mesh().n_vertices());
  histogram("##mesh_valences", session.mesh_valences(), 60.0f);
}

void comparison_section(Session& session) {
  bool compare = session.compare();
  if (ImGui::Checkbox("Compare", &compare)) session.set_compare(compare);
  ImGui::SameLine();
  int mode = session.compare_mode() == CompareMode::Weights ? 0 : 1;
  ImGui::SetNextItemWidth(125.0f);
  if (ImGui::Combo("##compare_mode", &mode, "liepa | maxmin\0umbrella | fair\0")) {
    session.set_compare_mode(mode == 0 ? CompareMode::Weights : CompareMode::Smoothing);
  }
  if (session.compare_mode() == CompareMode::Weights) {
    ImGui::SameLine();
    bool triangulation_only = session.compare_triangulation_only();
    if (ImGui::Checkbox("triangulation only", &triangulation_only)) {
      session.set_compare_triangulation_only(triangulation_only);
    }
  }
  const Comparison* comparison = session.comparison();
  if (!compare) return;
  if (!comparison) {
    ImGui::TextDisabled("Select a hole to compare.");
    return;
  }
  if (ImGui::BeginTable("compare", 2, ImGuiTableFlags_BordersInnerV)) {
    for (const ComparisonSide* side : {&comparison->left, &comparison->right}) {
      ImGui::TableNextColumn();
      ImGui::PushID(side == &comparison->left ? "left" : "right");
      ImGui::Text("%s (%s)", side->label.c_str(), side == &comparison->left ? "left" : "right");
      const PatchStats& s = side->fill.stats;
      if (side->fill.failed()) {
        ImGui::TextColored(kErrorColor, "failed");
      } else {
        ImGui::Text("+%zu vertices, +%zu faces", s.new_vertices, s.new_faces);
        ImGui::Text("min angle %.2f", s.min_angle_deg);
        ImGui::Text("max dihedral %.2f", s.max_dihedral_deg);
        ImGui::Text("area %.4g", s.area);
      }
      histogram("##valences", s.valence_histogram, 45.0f);
      ImGui::PopID();
    }
    ImGui::EndTable();
  }
}

ImVec4 color(const palette::Rgb& c) {
  return ImVec4(c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f, 1.0f);
}

void legend() {
  const std::pair<const palette::Rgb*, const char*> entries[] = {
      {&palette::kTriangulated, "triangulated"}, {&palette::kRefined, "refined"},
      {&palette::kPatchVertex, "new vertex"},    {&palette::kBoundary, "hole"},
      {&palette::kSelectedBoundary, "selected"}, {&palette::kHoveredBoundary, "hovered"}};
  for (std::size_t i = 0; i < std::size(entries); ++i) {
    if (i % 3) ImGui::SameLine();
    ImGui::TextColored(color(*entries[i].first), "# %-12s", entries[i].second);
  }
}

void display_section(UiState& ui) {
  legend();
  ImGui::Checkbox("wireframe", &ui.display.wireframe);
  ImGui::SameLine();
  ImGui::Checkbox("flat shading", &ui.display.flat);
  ImGui::SameLine();
  ImGui::Checkbox("new vertices", &ui.display.patch_vertices);
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - 100.0f);
  ImGui::InputText("##screenshot", &ui.screenshot_path);
  ImGui::SameLine();
  if (ImGui::Button("Screenshot")) ui.take_screenshot = true;
}

}  // namespace

void draw_panels(Session& session, FileActions& files, Worker& worker, UiState& ui,
                 float window_height) {
  ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
  ImGui::SetNextWindowSize(ImVec2(kPanelWidth, window_height));
  ImGui::Begin("holefill", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  file_section(session, files, ui);
  ImGui::Separator();
  hole_list(session, ui);
  ImGui::Separator();
  ImGui::BeginDisabled(worker.busy());
  options_section(session, ui);
  step_section(session, worker, ui);
  ImGui::EndDisabled();
  ImGui::Separator();
  statistics_section(session);
  ImGui::Separator();
  comparison_section(session);
  ImGui::Separator();
  display_section(ui);
  ImGui::End();
}

}  // namespace holefill::viewer
