#include "table.h"

#include <cstdio>
#include <iomanip>
#include <ostream>

namespace holefill::cli {

std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

std::string id_list(const std::vector<int>& ids) {
  std::string text;
  for (const int id : ids) {
    if (!text.empty()) text += ',';
    text += std::to_string(id);
  }
  return text;
}

void print_fill_table(const std::vector<HoleFill>& fills, std::ostream& out) {
  out << "  hole  boundary  stage          new_v   new_f  min_angle  max_dihedral  intersect"
         "   seconds\n";
  for (const auto& fill : fills) {
    const auto& s = fill.stats;
    const double seconds = fill.times.triangulate_seconds + fill.times.refine_seconds +
                           fill.times.smooth_seconds + fill.times.check_seconds;
    // A space between columns whatever the widths: huge values widen a row, never merge cells.
    out << std::setw(6) << fill.hole_id << ' ' << std::setw(9) << fill.boundary_edges << "  "
        << std::left << std::setw(13) << (fill.failed() ? "FAILED" : to_string(fill.stage()))
        << std::right << ' ' << std::setw(6) << s.new_vertices << ' ' << std::setw(7) << s.new_faces
        << ' ' << std::setw(10) << format("%.2f", s.min_angle_deg) << ' ' << std::setw(13)
        << format("%.2f", s.max_dihedral_deg) << ' ' << std::setw(10) << fill.self_intersections
        << ' ' << std::setw(9) << format("%.4f", seconds);
    if (!fill.joined_holes.empty()) out << "  with holes " << id_list(fill.joined_holes);
    out << "\n";
  }
}

}  // namespace holefill::cli
