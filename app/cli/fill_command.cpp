// `holefill fill MESH -o OUT`: check the outputs, fill the selected holes, write the mesh and the
// report, then print the table (after the files, so a closed stdout cannot cost them).
#include <algorithm>
#include <cctype>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "commands.h"
#include "holefill/errors.h"
#include "holefill/holes.h"
#include "mesh_input.h"
#include "outputs.h"
#include "preparation.h"
#include "progress_lines.h"
#include "report.h"
#include "table.h"

namespace holefill::cli {
namespace {

// "A,B": two different hole ids of the mesh, whose loops --max-boundary does not exclude.
std::pair<int, int> parse_bridge(const FillArguments& a, const std::string& text,
                                 const std::vector<Hole>& holes) {
  const std::size_t hole_count = holes.size();
  const std::size_t comma = text.find(',');
  std::vector<int> ids;
  for (const std::string& part :
       {text.substr(0, comma), comma == std::string::npos ? "" : text.substr(comma + 1)}) {
    if (part.empty() || part.size() > 9 ||
        !std::all_of(part.begin(), part.end(), [](unsigned char c) { return std::isdigit(c); })) {
      throw UsageError("--bridge takes two hole ids, A,B (e.g. --bridge 0,3), got '" + text + "'");
    }
    const int id = std::stoi(part);
    if (id >= static_cast<int>(hole_count)) {
      throw UsageError("--bridge: " + a.input + " has no hole " + part + " (it has " +
                       std::to_string(hole_count) + ")");
    }
    ids.push_back(id);
  }
  if (ids[0] == ids[1]) {
    throw UsageError("--bridge joins two different holes, got hole " + std::to_string(ids[0]) +
                     " twice ('" + text + "')");
  }
  // The band's loops (without any islands, which only add edges) over the limit: the bridge
  // would be left out of the fill without a word.
  const std::size_t edges = holes[ids[0]].size() + holes[ids[1]].size();
  const std::size_t most = a.selection.max_boundary_edges;
  if (most && edges > most) {
    throw UsageError("--bridge " + text + ": holes " + std::to_string(ids[0]) + " and " +
                     std::to_string(ids[1]) + " have " + std::to_string(edges) +
                     " boundary edges together, more than --max-boundary " + std::to_string(most) +
                     " fills");
  }
  return {ids[0], ids[1]};
}

void select_holes(FillArguments& a, const std::vector<Hole>& holes) {
  const std::size_t hole_count = holes.size();
  for (const std::int64_t id : a.hole_ids) {
    if (id >= static_cast<std::int64_t>(hole_count)) {
      throw UsageError("--holes: " + a.input + " has no hole " + std::to_string(id) + " (it has " +
                       std::to_string(hole_count) + ")");
    }
    a.selection.hole_ids.push_back(static_cast<int>(id));
  }
  for (const std::string& text : a.bridges) {
    a.selection.bridges.push_back(parse_bridge(a, text, holes));
  }
}

struct FillCounts {
  std::size_t filled = 0, intersecting = 0;
};

// The notes and failures of each hole on stderr.
FillCounts report_problems(const std::vector<HoleFill>& fills, const std::string& input,
                           std::ostream& err) {
  FillCounts counts;
  const std::string prefix = "holefill: " + input + ": hole ";
  for (const auto& fill : fills) {
    if (!fill.failed()) ++counts.filled;
    if (fill.self_intersections > 0) {
      ++counts.intersecting;
      err << prefix << fill.hole_id << ": the patch intersects the mesh ("
          << fill.self_intersections << " pairs of triangles)\n";
    }
    if (!fill.refinement_note.empty())
      err << prefix << fill.hole_id << ": " << fill.refinement_note << "\n";
    if (!fill.smoothing_note.empty())
      err << prefix << fill.hole_id << ": " << fill.smoothing_note << "\n";
    if (!fill.attributes_note.empty())
      err << prefix << fill.hole_id << ": " << fill.attributes_note << "\n";
    if (!fill.islands_note.empty())
      err << prefix << fill.hole_id << ": " << fill.islands_note << "\n";
    if (fill.failed()) err << prefix << fill.hole_id << " not filled: " << fill.failure << "\n";
  }
  return counts;
}

// Writes the mesh, then the report; says which one failed and what became of the other.
bool write_results(const Mesh& mesh, const ReportInput& report, const FillArguments& a,
                   const Streams& streams) {
  try {
    write_mesh_output(mesh, a, streams.out);
  } catch (const FileError& e) {
    streams.err << "holefill: " << e.what() << "; the filled mesh was not written"
                << (a.report_path.empty() ? "" : ", nor the report") << "\n";
    return false;
  }
  for (const auto& lost : mesh_output_losses(mesh, a)) {
    streams.err << "holefill: " << a.output
                << ": not written (the format cannot hold them): " << lost << "\n";
  }
  if (a.report_path.empty()) return true;
  try {
    write_output(a.report_path, json_report(report), streams.out);
  } catch (const FileError& e) {
    streams.err << "holefill: " << e.what()
                << "; the report was not written (the filled mesh was, to " << a.output << ")\n";
    return false;
  }
  return true;
}

void print_summary(const std::vector<HoleFill>& fills, const FillCounts& counts,
                   const ReportInput& report, std::ostream& out) {
  print_fill_table(fills, out);
  out << report.input_path << ": filled " << counts.filled << " of " << fills.size()
      << " selected holes (" << report.holes_before << " in all); " << report.holes_after
      << " holes remain";
  if (counts.intersecting) out << "; " << counts.intersecting << " patches intersect the mesh";
  out << "\n";
}

}  // namespace

int run_fill(FillArguments& a, const Streams& streams) {
  try {
    check_outputs(a);
  } catch (const FileError& e) {
    streams.err << "holefill: " << e.what() << "\n";
    return kWriteFailed;
  }
  Mesh mesh = load_and_warn(a.input, a.format, streams);
  const PreparedMesh prepared = prepare_mesh(mesh, a.preparation, a.input, streams.err);
  const auto& holes = prepared.holes;
  select_holes(a, holes);
  ReportInput report;
  report.input_path = a.input;
  report.output_path = a.output;
  report.options = &a.options;
  report.prepared = &prepared;
  report.vertices_before = mesh.n_vertices();
  report.faces_before = mesh.n_faces();
  report.holes_before = holes.size();

  // Holes listed with --holes are filled whatever they are; otherwise flat pieces and kept
  // borders are left out (they still come along as the islands of a hole that is filled).
  if (a.selection.hole_ids.empty()) a.selection.hole_ids = prepared.ids_to_fill;
  std::optional<ProgressLines> progress;
  if (streams.verbosity != Verbosity::Quiet) {
    progress.emplace(streams.err, a.input, streams.verbosity == Verbosity::Verbose);
  }
  const auto fills = a.selection.hole_ids.empty()
                         ? std::vector<HoleFill>{}
                         : fill_holes(mesh, holes, a.options, a.selection,
                                      progress ? &progress->progress() : nullptr);
  report.vertices_after = mesh.n_vertices();
  report.faces_after = mesh.n_faces();
  report.holes_after = find_holes(mesh).size();
  report.fills = &fills;

  const FillCounts counts = report_problems(fills, a.input, streams.err);
  const bool written = write_results(mesh, report, a, streams);
  if (streams.verbosity != Verbosity::Quiet) {
    print_summary(fills, counts, report, stdout_carries_a_file(a) ? streams.err : streams.out);
  }
  if (!written) return kWriteFailed;
  if (counts.filled != fills.size()) return kSomeHolesNotFilled;
  return counts.intersecting ? kPatchesIntersect : kOk;
}

}  // namespace holefill::cli
