#include "report.h"

#include <cmath>
#include <iomanip>
#include <ostream>

namespace holefill::cli {
namespace {

std::string quoted(const std::string& text) {
  std::string s = "\"";
  for (const char c : text) {
    switch (c) {
      case '"':
        s += "\\\"";
        break;
      case '\\':
        s += "\\\\";
        break;
      case '\n':
        s += "\\n";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buffer[8];
          std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
          s += buffer;
        } else {
          s += c;
        }
    }
  }
  return s + "\"";
}

std::string number(double value) {
  if (!std::isfinite(value)) return "null";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", value);
  return buffer;
}

void write_fill(const HoleFill& fill, std::ostream& out) {
  const PatchStats& s = fill.stats;
  out << "    {\"hole\": " << fill.hole_id << ", \"boundary_edges\": " << fill.boundary_edges
      << ", \"filled\": " << (fill.failed() ? "false" : "true")
      << ", \"stage\": " << quoted(to_string(fill.stage()));
  if (fill.failed()) out << ", \"failure\": " << quoted(fill.failure);
  if (!fill.refinement_note.empty()) {
    out << ", \"refinement_note\": " << quoted(fill.refinement_note);
  }
  if (!fill.smoothing_note.empty()) out << ", \"smoothing_note\": " << quoted(fill.smoothing_note);
  out << ", \"self_intersections\": " << fill.self_intersections;
  out << ",\n     \"new_vertices\": " << s.new_vertices << ", \"new_faces\": " << s.new_faces
      << ", \"min_angle_deg\": " << number(s.min_angle_deg)
      << ", \"mean_min_angle_deg\": " << number(s.mean_min_angle_deg)
      << ", \"max_dihedral_deg\": " << number(s.max_dihedral_deg)
      << ", \"area\": " << number(s.area) << ",\n     \"valence_histogram\": {";
  bool first = true;
  for (const auto& [valence, count] : s.valence_histogram) {
    out << (first ? "" : ", ") << "\"" << valence << "\": " << count;
    first = false;
  }
  out << "},\n     \"seconds\": {\"triangulate\": " << number(fill.times.triangulate_seconds)
      << ", \"refine\": " << number(fill.times.refine_seconds)
      << ", \"smooth\": " << number(fill.times.smooth_seconds)
      << ", \"checks\": " << number(fill.times.check_seconds) << "}}";
}

}  // namespace

void write_json_report(const ReportInput& in, std::ostream& out) {
  const FillOptions& o = *in.options;
  out << "{\n  \"input\": " << quoted(in.input_path)
      << ",\n  \"output\": " << quoted(in.output_path)
      << ",\n  \"options\": {\"weight\": " << quoted(to_string(o.triangulate.weight))
      << ", \"fold_limit_deg\": " << number(o.triangulate.fold_limit * 180.0 / M_PI)
      << ", \"restricted_above\": " << o.triangulate.restricted.above_edges
      << ", \"tau\": " << number(o.refine.tau)
      << ", \"remesh\": " << (o.refine.remesh ? "true" : "false")
      << ", \"smooth\": " << quoted(o.smooth.method == SmoothMethod::Fair ? "fair" : "umbrella")
      << ", \"fair_order\": " << o.smooth.fair.order
      << ", \"smooth_iterations\": " << o.smooth.iterations
      << ", \"smooth_step\": " << number(o.smooth.step)
      << ", \"last_stage\": " << quoted(to_string(o.last_stage)) << "},\n"
      << "  \"before\": {\"vertices\": " << in.vertices_before << ", \"faces\": " << in.faces_before
      << ", \"holes\": " << in.holes_before << "},\n"
      << "  \"after\": {\"vertices\": " << in.vertices_after << ", \"faces\": " << in.faces_after
      << ", \"holes\": " << in.holes_after << "},\n  \"holes\": [\n";
  for (std::size_t i = 0; i < in.fills->size(); ++i) {
    write_fill((*in.fills)[i], out);
    out << (i + 1 < in.fills->size() ? ",\n" : "\n");
  }
  out << "  ]\n}\n";
}

}  // namespace holefill::cli
