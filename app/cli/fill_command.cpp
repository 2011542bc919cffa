// `holefill fill MESH -o OUT`: fill the selected holes, write the mesh, the table and the report.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>

#include "commands.h"
#include "holefill/errors.h"
#include "holefill/holes.h"
#include "holefill/io.h"
#include "mesh_input.h"
#include "report.h"
#include "table.h"

namespace holefill::cli {
namespace {

void check_output_format(const std::string& output) {
  std::string ext = std::filesystem::path(output).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const auto& writable = writable_extensions();
  if (std::find(writable.begin(), writable.end(), ext) == writable.end()) {
    throw UsageError("-o " + output + ": cannot write '" + ext +
                     "' files (use .obj, .off or .ply)");
  }
}

void select_holes(FillArguments& a, std::size_t hole_count) {
  for (const std::int64_t id : a.hole_ids) {
    if (id >= static_cast<std::int64_t>(hole_count)) {
      throw UsageError("--holes: " + a.input + " has no hole " + std::to_string(id) + " (it has " +
                       std::to_string(hole_count) + ")");
    }
    a.selection.hole_ids.push_back(static_cast<int>(id));
  }
}

// The notes and failures of each hole on stderr; returns (filled, intersecting) counts.
std::pair<std::size_t, std::size_t> report_problems(const std::vector<HoleFill>& fills,
                                                    const std::string& input, std::ostream& err) {
  std::size_t filled = 0, intersecting = 0;
  const std::string prefix = "holefill: " + input + ": hole ";
  for (const auto& fill : fills) {
    if (!fill.failed()) ++filled;
    if (fill.self_intersections > 0) {
      ++intersecting;
      err << prefix << fill.hole_id << ": the patch intersects the mesh ("
          << fill.self_intersections << " pairs of triangles)\n";
    }
    if (!fill.refinement_note.empty())
      err << prefix << fill.hole_id << ": " << fill.refinement_note << "\n";
    if (!fill.smoothing_note.empty())
      err << prefix << fill.hole_id << ": " << fill.smoothing_note << "\n";
    if (fill.failed()) err << prefix << fill.hole_id << " not filled: " << fill.failure << "\n";
  }
  return {filled, intersecting};
}

bool write_report(const ReportInput& report, const std::string& path, std::ostream& err) {
  std::ostringstream json;
  write_json_report(report, json);
  const std::string temp = path + ".partial";
  std::ofstream file(temp, std::ios::binary);
  file << json.str();
  file.close();
  std::error_code ec;
  if (!file || (std::filesystem::rename(temp, path, ec), ec)) {
    std::filesystem::remove(temp, ec);
    err << "holefill: " << path << ": the report could not be written\n";
    return false;
  }
  return true;
}

}  // namespace

int run_fill(FillArguments& a, const Streams& streams) {
  check_output_format(a.output);
  Mesh mesh = load_and_warn(a.input, streams);
  const auto holes = find_holes(mesh);
  select_holes(a, holes.size());
  ReportInput report;
  report.input_path = a.input;
  report.output_path = a.output;
  report.options = &a.options;
  report.vertices_before = mesh.n_vertices();
  report.faces_before = mesh.n_faces();
  report.holes_before = holes.size();

  const auto fills = fill_holes(mesh, holes, a.options, a.selection);
  report.vertices_after = mesh.n_vertices();
  report.faces_after = mesh.n_faces();
  report.holes_after = find_holes(mesh).size();
  report.fills = &fills;

  const auto [filled, intersecting] = report_problems(fills, a.input, streams.err);
  if (streams.verbosity != Verbosity::Quiet) {
    print_fill_table(fills, streams.out);
    streams.out << a.input << ": filled " << filled << " of " << fills.size() << " selected holes ("
                << holes.size() << " in all); " << report.holes_after << " holes remain";
    if (intersecting) streams.out << "; " << intersecting << " patches intersect the mesh";
    streams.out << "\n";
  }
  try {
    save_mesh(mesh, a.output);
  } catch (const FileError& e) {
    streams.err << "holefill: " << e.what() << "\n";
    return kWriteFailed;
  }
  if (!a.report_path.empty() && !write_report(report, a.report_path, streams.err)) {
    return kWriteFailed;
  }
  if (filled != fills.size()) return kSomeHolesNotFilled;
  return intersecting ? kPatchesIntersect : kOk;
}

}  // namespace holefill::cli
