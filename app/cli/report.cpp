#include "report.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

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
          {"fold_limit_deg", o.triangulate.fold_limit * 180.0 / std::numbers::pi},
          {"restricted_above", o.triangulate.restricted.above_edges},
          {"tau", o.refine.tau},
          {"remesh", o.refine.remesh},
          {"islands", o.islands.detect ? "on" : "off"},
          {"feature_angle_deg", o.features.angle_degrees},
          {"smooth", o.smooth.method == SmoothMethod::Fair ? "fair" : "umbrella"},
          {"fair_order", o.smooth.fair.order},
          {"smooth_iterations", o.smooth.iterations},
          {"smooth_step", o.smooth.step},
          {"last_stage", to_string(o.last_stage)},
          {"allow_intersections", o.allow_intersections},
          {"threads", o.threads}};
}

// The feature lines entering a hole and how they continue (null when none enter).
Json features_json(const HoleFeatures& features, const std::string& note) {
  if (features.lines.empty()) return nullptr;
  Json junctions = Json::array();
  for (const auto& junction : features.junctions) {
    Json entries = Json::array();
    std::size_t new_vertices = junction.corner ? 1 : 0;
    for (const int l : junction.lines) entries.push_back(features.lines[l].entry);
    for (const auto& path : junction.paths) new_vertices += path.size();
    Json entry{{"kind", junction.corner ? "corner" : "crease"},
               {"entries", std::move(entries)},
               {"new_vertices", new_vertices}};
    if (junction.corner) {
      const Point& p = junction.corner_point;
      entry["corner_point"] = {p[0], p[1], p[2]};
    }
    junctions.push_back(std::move(entry));
  }
  Json entry{{"lines", features.lines.size()},
             {"continued", features.continued() && note.empty()},
             {"junctions", std::move(junctions)}};
  if (!note.empty()) entry["note"] = note;
  return entry;
}

Json fill_json(const HoleFill& fill) {
  const PatchStats& s = fill.stats;
  Json entry{{"hole", fill.hole_id},
             {"joined_holes", fill.joined_holes},
             {"boundary_edges", fill.boundary_edges},
             {"filled", !fill.failed()},
             {"stage", to_string(fill.stage())}};
  if (fill.failed()) {
    entry["failure"] = fill.failure.message;
    entry["failure_kind"] = to_string(fill.failure.kind);
  }
  if (!fill.refinement_note.empty()) entry["refinement_note"] = fill.refinement_note;
  if (!fill.smoothing_note.empty()) entry["smoothing_note"] = fill.smoothing_note;
  if (!fill.attributes_note.empty()) entry["attributes_note"] = fill.attributes_note;
  if (!fill.islands_note.empty()) entry["islands_note"] = fill.islands_note;
  if (!fill.features.lines.empty()) {
    entry["features"] = features_json(fill.features, fill.features_note);
  }
  entry["self_intersections"] = fill.self_intersections;
  if (fill.refused_intersections > 0) entry["refused_intersections"] = fill.refused_intersections;
  const IntersectionAvoidance& avoidance = fill.avoidance;
  entry["intersection_avoidance"] = {{"first_pairs", avoidance.first_pairs},
                                     {"rounds", avoidance.rounds},
                                     {"changed", avoidance.changed}};
  if (avoidance.changed) {
    entry["intersection_avoidance"]["weight"] = to_string(avoidance.weight);
  }
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
                      {"checks", fill.times.check_seconds},
                      {"avoid_intersections", fill.times.avoid_seconds}};
  return entry;
}

// Stitching (null when off), the mesh's pieces, and every loop that is not a plain hole.
void add_preparation(const PreparedMesh& p, Json& document) {
  if (p.stitched) {
    document["stitch"] = {{"tolerance", p.stitch.tolerance},
                          {"edges_stitched", p.stitch.edges_stitched},
                          {"seams", p.stitch.seams},
                          {"vertices_merged", p.stitch.vertices_merged},
                          {"largest_distance", p.stitch.largest_distance},
                          {"edges_left_apart", p.stitch.edges_left_apart},
                          {"t_junctions", p.stitch.t_junctions}};
    document["weld"] = {{"positions", p.weld.positions},
                        {"vertices_welded", p.weld.vertices_welded},
                        {"positions_left", p.weld.positions_left}};
  } else {
    document["stitch"] = nullptr;
  }
  document["pieces"] = {{"count", p.pieces.pieces},
                        {"lone_triangles", p.pieces.lone_triangles},
                        {"small_pieces", p.pieces.small_pieces},
                        {"largest_small_piece_faces", p.pieces.largest_small_piece},
                        {"removed",
                         {{"pieces", p.removed.pieces},
                          {"faces", p.removed.faces},
                          {"vertices", p.removed.vertices}}}};
  Json special = Json::array();
  for (std::size_t i = 0; i < p.holes.size(); ++i) {
    const LoopClass& c = p.classes[i];
    if (c.kind == LoopKind::Hole && p.holes[i].repeated_vertices == 0) continue;
    Json entry{{"hole", p.holes[i].id},
               {"kind", to_string(c.kind)},
               {"pinched_vertices", p.holes[i].repeated_vertices},
               {"spanned_share", c.spanned_share},
               {"on_small_piece", c.on_small_piece}};
    if (!c.reason.empty()) entry["reason"] = c.reason;
    special.push_back(std::move(entry));
  }
  document["loops"] = {{"count", p.holes.size()},
                       {"pinched", p.pinched_loops},
                       {"borders_kept", p.borders_kept},
                       {"not_plain_holes", std::move(special)}};
}

}  // namespace

std::string json_report(const ReportInput& in) {
  Json holes = Json::array();
  for (const auto& fill : *in.fills) holes.push_back(fill_json(fill));
  Json document{
      {"input", in.input_path}, {"output", in.output_path}, {"options", options_json(*in.options)}};
  add_preparation(*in.prepared, document);
  document.update(Json{
      {"before",
       {{"vertices", in.vertices_before}, {"faces", in.faces_before}, {"holes", in.holes_before}}},
      {"after",
       {{"vertices", in.vertices_after}, {"faces", in.faces_after}, {"holes", in.holes_after}}},
      {"holes", std::move(holes)}});
  return text_of(document);
}

std::string features_summary(const HoleFeatures& features) {
  const std::size_t n = features.lines.size();
  if (n == 0) return {};
  std::string kinds;
  for (const auto& junction : features.junctions) {
    kinds += std::string(kinds.empty() ? "" : "+") + (junction.corner ? "corner" : "crease");
  }
  return "features: " + std::to_string(n) + (n == 1 ? " line, " : " lines, ") +
         (features.continued() ? kinds : "not continued");
}

std::string json_info(const std::string& input_path, const Mesh& mesh, const PreparedMesh& prepared,
                      const FeatureOptions& features) {
  const IslandMap& islands = prepared.islands;
  Json list = Json::array();
  for (std::size_t i = 0; i < prepared.holes.size(); ++i) {
    const Hole& hole = prepared.holes[i];
    Json entry{{"id", hole.id},
               {"boundary_edges", hole.size()},
               {"perimeter", hole.perimeter},
               {"pinched", hole.pinched},
               {"kind", to_string(prepared.classes[i].kind)},
               {"islands", islands.islands[hole.id]}};
    if (islands.outer[hole.id] >= 0) entry["island_of"] = islands.outer[hole.id];
    if (!islands.note[hole.id].empty()) entry["islands_note"] = islands.note[hole.id];
    const HoleFeatures found = find_hole_features(mesh, hole, features);
    if (!found.lines.empty()) entry["features"] = features_json(found, found.note);
    list.push_back(std::move(entry));
  }
  const SurfaceCounts counts = surface_counts(mesh);
  Json document{{"input", input_path},
                {"vertices", mesh.n_vertices()},
                {"unused_vertices", counts.unused_vertices},
                {"faces", mesh.n_faces()},
                {"components", counts.components}};
  add_preparation(prepared, document);
  document["holes"] = std::move(list);
  return text_of(document);
}

}  // namespace holefill::cli
