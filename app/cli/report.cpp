#include "report.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "holefill/islands.h"
#include "holefill/stats.h"

namespace holefill::cli {
namespace {

using Json = nlohmann::ordered_json;  // keys in the order written, as a reader expects them

std::string text_of(const Json& document) {
  return document.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

Json options_json(const FillOptions& o) {
  return {{"weight", to_string(o.triangulate.weight)},
          {"fold_limit_deg", o.triangulate.fold_limit * 180.0 / M_PI},
          {"restricted_above", o.triangulate.restricted.above_edges},
          {"tau", o.refine.tau},
          {"remesh", o.refine.remesh},
          {"islands", o.islands.detect ? "on" : "off"},
          {"smooth", o.smooth.method == SmoothMethod::Fair ? "fair" : "umbrella"},
          {"fair_order", o.smooth.fair.order},
          {"smooth_iterations", o.smooth.iterations},
          {"smooth_step", o.smooth.step},
          {"last_stage", to_string(o.last_stage)}};
}

Json fill_json(const HoleFill& fill) {
  const PatchStats& s = fill.stats;
  Json entry{{"hole", fill.hole_id},
             {"joined_holes", fill.joined_holes},
             {"boundary_edges", fill.boundary_edges},
             {"filled", !fill.failed()},
             {"stage", to_string(fill.stage())}};
  if (fill.failed()) entry["failure"] = fill.failure;
  if (!fill.refinement_note.empty()) entry["refinement_note"] = fill.refinement_note;
  if (!fill.smoothing_note.empty()) entry["smoothing_note"] = fill.smoothing_note;
  entry["self_intersections"] = fill.self_intersections;
  entry["new_vertices"] = s.new_vertices;
  entry["new_faces"] = s.new_faces;
  entry["min_angle_deg"] = s.min_angle_deg;  // not finite (no triangle): dumped as null
  entry["mean_min_angle_deg"] = s.mean_min_angle_deg;
  entry["max_dihedral_deg"] = s.max_dihedral_deg;
  entry["area"] = s.area;
  Json histogram = Json::object();
  for (const auto& [valence, count] : s.valence_histogram) {
    histogram[std::to_string(valence)] = count;
  }
  entry["valence_histogram"] = std::move(histogram);
  entry["seconds"] = {{"triangulate", fill.times.triangulate_seconds},
                      {"refine", fill.times.refine_seconds},
                      {"smooth", fill.times.smooth_seconds},
                      {"checks", fill.times.check_seconds}};
  return entry;
}

}  // namespace

std::string json_report(const ReportInput& in) {
  Json holes = Json::array();
  for (const auto& fill : *in.fills) holes.push_back(fill_json(fill));
  const Json document{
      {"input", in.input_path},
      {"output", in.output_path},
      {"options", options_json(*in.options)},
      {"before",
       {{"vertices", in.vertices_before}, {"faces", in.faces_before}, {"holes", in.holes_before}}},
      {"after",
       {{"vertices", in.vertices_after}, {"faces", in.faces_after}, {"holes", in.holes_after}}},
      {"holes", std::move(holes)}};
  return text_of(document);
}

std::string json_info(const std::string& input_path, const Mesh& mesh,
                      const std::vector<Hole>& holes) {
  const IslandMap islands = find_islands(mesh, holes);
  Json list = Json::array();
  for (const auto& hole : holes) {
    Json entry{{"id", hole.id},
               {"boundary_edges", hole.size()},
               {"perimeter", hole.perimeter},
               {"pinched", hole.pinched},
               {"islands", islands.islands[hole.id]}};
    if (islands.outer[hole.id] >= 0) entry["island_of"] = islands.outer[hole.id];
    if (!islands.problem[hole.id].empty()) entry["problem"] = islands.problem[hole.id];
    list.push_back(std::move(entry));
  }
  const Json document{{"input", input_path},
                      {"vertices", mesh.n_vertices()},
                      {"faces", mesh.n_faces()},
                      {"components", connected_components(mesh)},
                      {"holes", std::move(list)}};
  return text_of(document);
}

}  // namespace holefill::cli
