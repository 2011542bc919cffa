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
#include "disabled_reasons.h"
#include "hole_list_panel.h"
#include "palette.h"
#include "settings_panel.h"
#include "status_bar.h"
#include "valence_bins.h"
#include "widgets.h"

namespace holefill::viewer {
namespace {

constexpr float kSqrt2 = 1.41421356f;

// A bar per valence bin (valence_bins: the same bins for every chart) with its label under it
// and the count on hover; `log`: heights on a log scale.
void histogram(const char* id, const std::map<int, std::size_t>& valences, float height, bool log) {
  const auto bins = valence_bins(valences);
  std::size_t most = 0, total = 0;
  for (const auto& bin : bins) {
    most = std::max(most, bin.count);
    total += bin.count;
  }
  if (total == 0) {
    ImGui::TextDisabled("(no vertices)");
    return;
  }
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float width = ImGui::GetContentRegionAvail().x;
  ImGui::InvisibleButton(id, ImVec2(width, height + ImGui::GetTextLineHeight()));
  const bool hovered = ImGui::IsItemHovered();
  const float base = origin.y + height;
  const float slot = width / static_cast<float>(bins.size());
  std::array<float, kValenceBins> label_widths{};
  for (std::size_t i = 0; i < bins.size(); ++i)
    label_widths[i] = ImGui::CalcTextSize(bins[i].label).x;
  const auto label_x = label_positions(label_widths, width, scaled(4.0f));
  draw->AddRectFilled(origin, ImVec2(origin.x + width, base), ImGui::GetColorU32(ImGuiCol_FrameBg));
  for (std::size_t i = 0; i < bins.size(); ++i) {
    const float left = origin.x + slot * static_cast<float>(i);
    const bool over =
        hovered && ImGui::GetIO().MousePos.x >= left && ImGui::GetIO().MousePos.x < left + slot;
    const float bar =
        static_cast<float>(bar_height(bins[i].count, most, log)) * (height - scaled(4.0f));
    if (bins[i].count > 0) {
      draw->AddRectFilled(
          ImVec2(left + scaled(2.0f), base - std::max(bar, 1.0f)),
          ImVec2(left + slot - scaled(2.0f), base),
          ImGui::GetColorU32(over ? ImGuiCol_PlotHistogramHovered : ImGuiCol_PlotHistogram));
    }
    if (label_x[i]) {
      draw->AddText(ImVec2(origin.x + *label_x[i], base), ImGui::GetColorU32(ImGuiCol_TextDisabled),
                    bins[i].label);
    }
    if (over) {
      ImGui::SetTooltip("valence %s: %zu vertices (%.1f %%)", bins[i].label, bins[i].count,
                        100.0 * static_cast<double>(bins[i].count) / static_cast<double>(total));
    }
  }
  draw->AddLine(ImVec2(origin.x, base), ImVec2(origin.x + width, base),
                ImGui::GetColorU32(ImGuiCol_Text));
  char tallest[48];
  std::snprintf(tallest, sizeof tallest, "%zu%s", most, log ? " (log)" : "");
  draw->AddText(ImVec2(origin.x + 3.0f, origin.y + 1.0f), ImGui::GetColorU32(ImGuiCol_TextDisabled),
                tallest);
}

// The selected hole's patch: its stage on the heading line (the stage times on hover), then its
// measures and the valences of its new vertices.
void patch_statistics(int hole_id, const HoleFill& fill, bool log_valences) {
  if (fill.failed()) {  // why is said under the hole list
    ImGui::Text("Hole %d:", hole_id);
    ImGui::SameLine();
    ImGui::TextDisabled("not filled");
    return;
  }
  if (fill.stage() == Stage::Original) {
    ImGui::Text("Hole %d:", hole_id);
    ImGui::SameLine();
    ImGui::TextDisabled("not filled yet");
    return;
  }
  const PatchStats& s = fill.stats;
  ImGui::Text("Hole %d patch: %s", hole_id, to_string(fill.stage()));
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("Times: triangulation %.1f ms, refinement %.1f ms, smoothing %.1f ms",
                      1e3 * fill.times.triangulate_seconds, 1e3 * fill.times.refine_seconds,
                      1e3 * fill.times.smooth_seconds);
  }
  ImGui::Text("New vertices %zu   new faces %zu", s.new_vertices, s.new_faces);
  ImGui::Text("Min angle %.2f deg (mean %.2f)", s.min_angle_deg, s.mean_min_angle_deg);
  ImGui::Text("Max dihedral %.2f deg   area %.4g units^2", s.max_dihedral_deg, s.area);
  if (!fill.smoothing_note.empty()) ImGui::TextWrapped("%s", fill.smoothing_note.c_str());
  if (s.new_vertices == 0) return;
  ImGui::TextUnformatted("Valences of the patch's new vertices");
  histogram("##patch_valences", s.valence_histogram, scaled(30.0f), log_valences);
}

void file_section(const Session& session, FileActions& files, UiState& ui) {
  if (ImGui::Button("Open...")) files.open();
  tooltip("Open a mesh (Ctrl+O); or drop a file on the window");
  ImGui::SameLine();
  const bool no_mesh = session.mesh().n_vertices() == 0;
  ImGui::BeginDisabled(no_mesh);
  if (ImGui::Button("Save")) files.save();
  const std::string save_tip =
      files.save_target()
          ? "Save to " + files.save_target()->string() + " (Ctrl+S)"
          : std::string("Save the filled mesh: asks where, the first time (Ctrl+S)");
  tooltip(save_tip.c_str(), no_mesh ? "No mesh is open" : "");
  ImGui::SameLine();
  if (ImGui::Button("Save As...")) files.save_as();
  tooltip("Save the filled mesh as OBJ, OFF, PLY or STL (Ctrl+Shift+S)",
          no_mesh ? "No mesh is open" : "");
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button("Keys (F1)")) ui.show_help = true;
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
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - scaled(70.0f));
  edit.after_item(ImGui::SliderFloat("##tau", &tau, 1.0f, 2.0f, "tau = %.3f"));
  tooltip(
      "Refinement density: a triangle is split while tau times the distance from its centroid "
      "to a corner exceeds the corners' edge scale. Larger tau: denser patch. The tick is "
      "sqrt 2 (the paper's).");
  const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
  const float grab = ImGui::GetStyle().GrabMinSize;
  const float x = lo.x + grab * 0.5f + (kSqrt2 - 1.0f) * (hi.x - lo.x - grab);
  ImGui::GetWindowDrawList()->AddLine(ImVec2(x, lo.y), ImVec2(x, lo.y + scaled(5.0f)),
                                      IM_COL32(255, 220, 90, 255), 2.0f);
  ImGui::GetWindowDrawList()->AddLine(ImVec2(x, hi.y - scaled(5.0f)), ImVec2(x, hi.y),
                                      IM_COL32(255, 220, 90, 255), 2.0f);
  ImGui::SameLine();
  if (ImGui::Button("sqrt 2")) {
    tau = kSqrt2;
    return true;
  }
  return false;
}

// Combos, checkboxes and buttons apply at once; sliders show their value while dragged and
// apply it where the user lets go, so a drag re-runs the fill once, not at every step. The
// selected hole's steps re-run on the worker; meanwhile the new values stay shown.
void options_section(Session& session, Worker& worker, UiState& ui) {
  if (!worker.busy()) ui.applying_options.reset();
  FillOptions options =
      ui.dragged_options.value_or(ui.applying_options.value_or(session.options()));
  bool changed = false;
  SliderEdit slider;
  const WeightKind kinds[] = {WeightKind::MaxMin, WeightKind::Liepa, WeightKind::Area};
  ImGui::SetNextItemWidth(scaled(150.0f));
  if (ImGui::BeginCombo("weight", to_string(options.triangulate.weight).c_str())) {
    for (const auto kind : kinds) {
      if (ImGui::Selectable(to_string(kind).c_str(), kind == options.triangulate.weight)) {
        options.triangulate.weight = kind;
        changed = true;
      }
    }
    ImGui::EndCombo();
  }
  tooltip(
      "How the first stage triangulates the hole: maxmin (the paper's) maximises the smallest "
      "angle, then minimises the largest dihedral angle; liepa minimises the dihedral angle, "
      "then the area; area minimises the area");
  float tau = static_cast<float>(options.refine.tau);
  changed |= tau_slider(tau, slider);
  if (changed || slider.moved)
    options.refine.tau = std::abs(tau - kSqrt2) < 1e-6f ? std::sqrt(2.0) : tau;
  changed |= ImGui::Checkbox("remesh to valence 6", &options.refine.remesh);
  tooltip(
      "After refinement: valence-driven flips and tangential relaxation of the patch (not in "
      "the paper)");
  ImGui::SameLine();
  changed |= ImGui::Checkbox("keep cutting patches", &options.allow_intersections);
  tooltip(
      "Off (the default): a hole whose every patch tried intersects the mesh is left open. On: "
      "its best patch is kept anyway, its intersections counted and shown");
  // 0: umbrella; 1, 2: fairing of order 2 (bi-Laplacian) or 3 (tri-Laplacian).
  const bool fair = options.smooth.method == SmoothMethod::Fair;
  int method = fair ? options.smooth.fair.order - 1 : 0;
  ImGui::SetNextItemWidth(scaled(150.0f));
  if (ImGui::Combo("smoothing", &method, "umbrella (paper)\0fair (order 2)\0fair (order 3)\0")) {
    options.smooth.method = method > 0 ? SmoothMethod::Fair : SmoothMethod::Umbrella;
    if (method > 0) options.smooth.fair.order = method + 1;
    changed = true;
  }
  tooltip(
      "umbrella: the paper's Laplacian smoothing; fair: bi- (order 2) or tri-Laplacian (order 3) "
      "fairing that continues the surrounding curvature");
  ImGui::BeginDisabled(fair);  // the umbrella operator's own settings
  ImGui::SetNextItemWidth(scaled(150.0f));
  slider.after_item(ImGui::SliderInt("smoothing iterations", &options.smooth.iterations, 0, 100));
  tooltip("Umbrella smoothing: how many times each new vertex moves toward its neighbours' mean");
  float step = static_cast<float>(options.smooth.step);
  ImGui::SetNextItemWidth(scaled(150.0f));
  const bool stepped = ImGui::SliderFloat("smoothing step", &step, 0.05f, 1.0f, "%.2f");
  slider.after_item(stepped);
  tooltip("Umbrella smoothing: the share of the way toward the mean each iteration moves");
  if (stepped) options.smooth.step = step;
  ImGui::EndDisabled();
  float angle = static_cast<float>(options.features.angle_degrees);
  ImGui::SetNextItemWidth(scaled(150.0f));
  const bool angled = ImGui::SliderFloat("feature angle", &angle, 0.0f, 90.0f, "%.0f deg");
  slider.after_item(angled);
  tooltip(
      "Sharp features continued through the hole: edges around it whose faces turn by more "
      "than this are traced (yellow) and joined across the hole (green) when they pair up, and "
      "the regions between them are filled apart. 0 turns it off");
  if (angled) options.features.angle_degrees = angle;
  if (changed || slider.released) {
    ui.dragged_options.reset();
    if (start_options(worker, session, options) && worker.busy()) ui.applying_options = options;
  } else if (slider.moved) {
    ui.dragged_options = options;
  }
}

// A button that is greyed out, with a tooltip that says why, unless `why_not` is empty (then
// `what` explains it). While the worker runs every one of them says so.
bool action_button(const char* label, const Worker& worker, const std::string& why_not,
                   const char* what) {
  const std::string reason = worker.busy() ? kBusyReason : why_not;
  ImGui::BeginDisabled(!reason.empty());
  const bool pressed = ImGui::Button(label);
  ImGui::EndDisabled();
  tooltip(what, reason);
  return pressed;
}

void step_section(Session& session, Worker& worker, UiState& ui) {
  const auto stage_button = [&](const char* label, Stage stage, const char* what) {
    if (action_button(label, worker, why_not_step(session, stage), what))
      start_fill(worker, session, session.step_request(stage));
  };
  stage_button("Triangulate", Stage::Triangulated,
               "Close the selected hole with a minimal-weight triangulation (the first stage)");
  ImGui::SameLine();
  stage_button("Refine", Stage::Refined,
               "Split and swap the patch's triangles to the density of the mesh around it");
  ImGui::SameLine();
  stage_button("Smooth", Stage::Smoothed, "Smooth the patch's new vertices");
  ImGui::SameLine();
  if (action_button("Fill", worker, why_not_fill_selected(session),
                    "The selected hole's remaining stages (Shift+F)"))
    start_fill(worker, session, session.fill_selected_request());
  ImGui::SameLine();
  if (action_button("Reset hole", worker, why_not_reset(session),
                    "Take the selected hole's patch out again (Delete)"))
    start_change(worker, session, session.reset_request());

  const auto limit = static_cast<std::size_t>(ui.fill_all_max_edges);
  if (action_button(limit ? "Fill holes up to" : "Fill all holes", worker,
                    why_not_fill_all(session, limit),
                    "Every open hole's remaining stages (with its islands; borders of open "
                    "surfaces are left for you to fill one by one), on a worker: Cancel leaves "
                    "the mesh as it was (Ctrl+F)"))
    start_fill(worker, session, session.fill_all_request(limit));
  ImGui::SameLine();
  ImGui::SetNextItemWidth(scaled(90.0f));
  if (ImGui::InputInt("edges##limit", &ui.fill_all_max_edges, 10, 100))
    ui.fill_all_max_edges = std::max(ui.fill_all_max_edges, 0);
  tooltip(
      "Fill only holes of at most this many boundary edges (0: every hole), like the "
      "command line's --max-boundary");
  ImGui::SameLine();
  if (action_button("Undo", worker, why_not_undo(session), "Ctrl+Z"))
    start_change(worker, session, session.undo_request());
  ImGui::SameLine();
  if (action_button("Redo", worker, why_not_redo(session), "Ctrl+Y or Ctrl+Shift+Z"))
    start_change(worker, session, session.redo_request());
}

void statistics_section(Session& session, UiState& ui) {
  if (session.selected() >= 0) {
    patch_statistics(session.selected(), session.fill(session.selected()), ui.log_valences);
  } else {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped("Select a hole: click on or inside its outline, or in the list.");
    ImGui::PopStyleColor();
  }
  // The comparison's own charts take the room while it shows.
  if (session.compare() && session.selected() >= 0) return;
  ImGui::Text("Valences of the whole mesh (%zu vertices)", session.mesh().n_vertices());
  ImGui::SameLine();
  ImGui::Checkbox("log", &ui.log_valences);
  tooltip("Bar heights on a log scale, so that rare valences of a big mesh stay visible");
  histogram("##mesh_valences", session.mesh_valences(), scaled(30.0f), ui.log_valences);
}

void comparison_section(Session& session, Worker& worker, const UiState& ui) {
  bool compare = session.compare();
  if (ImGui::Checkbox("Compare", &compare)) session.set_compare(compare);
  tooltip(
      "Fill the selected hole two ways side by side, with one camera: the weights (liepa | "
      "maxmin), the smoothing (umbrella | fair) or the sharp features (the paper's fill | "
      "creases continued); the mesh is not changed until Keep this");
  ImGui::SameLine();
  int mode = static_cast<int>(session.compare_mode());
  // As wide as its longest entry and the arrow, so that no entry is cut.
  ImGui::SetNextItemWidth(ImGui::CalcTextSize("paper | creases").x + ImGui::GetFrameHeight() +
                          2.0f * ImGui::GetStyle().FramePadding.x);
  if (ImGui::Combo("##compare_mode", &mode, "liepa | maxmin\0umbrella | fair\0paper | creases\0")) {
    session.set_compare_mode(static_cast<CompareMode>(mode));
  }
  tooltip("What the two sides differ in");
  if (session.compare_mode() == CompareMode::Weights) {
    ImGui::SameLine();
    bool triangulation_only = session.compare_triangulation_only();
    if (ImGui::Checkbox("first stage only", &triangulation_only)) {
      session.set_compare_triangulation_only(triangulation_only);
    }
    tooltip("Compare the first stage alone, where the weights differ most");
  }
  const Comparison* comparison = session.shown_comparison();
  if (!compare) return;
  if (!comparison) {
    ImGui::TextDisabled(session.selected() < 0 ? "Select a hole to compare."
                                               : "Making the comparison...");
    return;
  }
  if (!ImGui::BeginTable("compare", 2, ImGuiTableFlags_BordersInnerV)) return;
  const ComparisonSide* sides[] = {&comparison->left, &comparison->right};
  for (const ComparisonSide* side : sides) {
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
    histogram("##valences", s.valence_histogram, scaled(30.0f), ui.log_valences);
    ImGui::PopID();
  }
  // The buttons on a row of their own: a cell that ends with a framed widget lowers the next
  // cell's first line by the frame's padding (ImGui aligns a row's text baselines).
  for (const ComparisonSide* side : sides) {
    ImGui::TableNextColumn();
    ImGui::PushID(side == &comparison->left ? "left" : "right");
    if (action_button("Keep this", worker,
                      side->fill.failed() ? "This side failed: there is nothing to keep" : "",
                      "Fill the hole with this side's options (they become the current ones)"))
      start_change(worker, session, session.keep_request(side == &comparison->right));
    ImGui::PopID();
  }
  ImGui::EndTable();
}

void legend() {
  const std::pair<const palette::Rgb*, const char*> entries[] = {
      {&palette::kTriangulated, "triangulated"},
      {&palette::kRefined, "refined"},
      {&palette::kSmoothed, "smoothed"},
      {&palette::kBoundary, "hole"},
      {&palette::kSelectedBoundary, "selected"},
      {&palette::kJoinedBoundary, "island/bridged"},
      {&palette::kBorder, "border"},
      {&palette::kHoveredBoundary, "hovered"},
      {&palette::kPatchVertex, "new vertex"},
      {&palette::kFeatureLine, "feature line"},
      {&palette::kFeaturePath, "continued"}};
  for (std::size_t i = 0; i < std::size(entries); ++i) {
    if (i % 3) ImGui::SameLine();
    ImGui::TextColored(color(*entries[i].first), "# %-12s", entries[i].second);
  }
}

void display_section(UiState& ui) {
  legend();
  ImGui::Checkbox("wireframe", &ui.display.wireframe);
  tooltip(
      "Draw the mesh's edges (off at first on meshes of over 200,000 faces, where they cover "
      "the surface and cost most of the frame)");
  ImGui::SameLine();
  ImGui::Checkbox("flat shading", &ui.display.flat);
  tooltip("One normal per face, so that every triangle shows");
  ImGui::SameLine();
  ImGui::Checkbox("new vertices", &ui.display.patch_vertices);
  tooltip("Dots on the vertices the fills added (thinned out where they crowd)");
  ImGui::Checkbox("feature lines", &ui.display.feature_lines);
  tooltip("The sharp feature lines entering the selected hole and how they continue across it");
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - scaled(100.0f));
  ImGui::InputText("##screenshot", &ui.screenshot_path);
  tooltip(
      "Where Screenshot and F12 save the window as PNG; a number is added rather than "
      "replacing a file");
  ImGui::SameLine();
  if (ImGui::Button("Screenshot")) ui.take_screenshot = true;
  tooltip("Save the window as PNG (F12)");
}

// The hole list, unless there is no mesh to show yet: then what is happening (opening, or how
// to open one). False when the sections about the mesh are left out.
bool mesh_sections(Session& session, const FileActions& files, Worker& worker, UiState& ui) {
  if (opening(worker)) {
    ImGui::Text("%s...", worker.label().c_str());
    if (session.mesh().n_vertices() == 0) return false;
  } else if (session.mesh().n_vertices() == 0) {
    ImGui::TextWrapped("No mesh is open: Open... (Ctrl+O), or drop a file on the window.");
    return false;
  }
  draw_hole_list(session, files, worker, ui);
  return true;
}

}  // namespace

void draw_comparison_labels(Session& session, float left, float right, float top) {
  const Comparison* comparison = session.shown_comparison();
  if (!comparison) return;
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const float half = 0.5f * (right - left);
  for (const ComparisonSide* side : {&comparison->left, &comparison->right}) {
    const float start = side == &comparison->left ? left : left + half;
    // On one line where the half is wide enough, else the name above the result.
    char text[96];
    for (const char* separator : {": ", ":\n"}) {
      std::snprintf(text, sizeof text, "%s%s%s, %zu new vertices", side->label.c_str(), separator,
                    side->fill.failed() ? "failed" : to_string(side->fill.stage()),
                    side->fill.stats.new_vertices);
      if (ImGui::CalcTextSize(text).x + scaled(24.0f) <= half) break;
    }
    const ImVec2 size = ImGui::CalcTextSize(text);
    const ImVec2 at(start + 0.5f * (half - size.x), top + scaled(8.0f));
    draw->AddRectFilled(ImVec2(at.x - scaled(6.0f), at.y - scaled(3.0f)),
                        ImVec2(at.x + size.x + scaled(6.0f), at.y + size.y + scaled(3.0f)),
                        IM_COL32(20, 22, 28, 220), 4.0f);
    draw->AddText(at, ImGui::GetColorU32(ImGuiCol_Text), text);
  }
}

void draw_panels(Session& session, FileActions& files, Worker& worker, UiState& ui,
                 float window_height) {
  ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
  ImGui::SetNextWindowSize(ImVec2(ui.scale.panel_width(), window_height));
  ImGui::Begin("holefill", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  file_section(session, files, ui);
  ImGui::Separator();
  // Everything but the status bar scrolls in the room above it.
  ImGui::BeginChild("##controls", ImVec2(0.0f, -status_bar_height()));
  if (mesh_sections(session, files, worker, ui)) {
    ImGui::Separator();
    ImGui::BeginDisabled(worker.busy());
    options_section(session, worker, ui);
    step_section(session, worker, ui);
    ImGui::EndDisabled();
    ImGui::Separator();
    statistics_section(session, ui);
    ImGui::Separator();
    comparison_section(session, worker, ui);
  }
  ImGui::Separator();
  display_section(ui);
  threads_setting(session, worker);
  remove_pieces_button(session, files, worker);
  ImGui::EndChild();
  draw_status_bar(session, ui.notices);
  ImGui::End();
}

}  // namespace holefill::viewer
