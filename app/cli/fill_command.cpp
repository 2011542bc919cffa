// `holefill fill MESH -o OUT`: check the outputs, fill the selected holes, write the mesh and the
// report, then print the table (after the files, so a closed stdout cannot cost them).
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "commands.h"
#include "hole_selection.h"
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
    // Features that matched but could not be followed; lines without partners (most often a
    // scan's noise, on organic meshes) are in the report only.
    if (!fill.features_note.empty() && fill.features.continued())
      err << prefix << fill.hole_id << ": " << fill.features_note << "\n";
    if (fill.failed()) {
      // The core says what went wrong, the command names its own option that helps.
      const char* remedy = fill.refused_intersections ? "; --allow-intersections keeps it"
                           : fill.failure.kind == FailureKind::VertexPassedTooOften
                               ? "; --remove-small-components N removes pieces of at most N faces"
                               : "";
      err << prefix << fill.hole_id << " not filled: " << fill.failure.message << remedy << "\n";
    }
  }
  return counts;
}

// Writes the mesh, then the report; says which one failed and what became of the other.
bool write_results(const Mesh& mesh, MeshFormat format, const ReportInput& report,
                   const FillArguments& a, const Streams& streams) {
  try {
    write_mesh_output(mesh, format, a, streams.out);
  } catch (const FileError& e) {
    streams.err << "holefill: " << e.what() << "; the filled mesh was not written"
                << (a.report_path.empty() ? "" : ", nor the report") << "\n";
    return false;
  }
  for (const auto& lost : mesh_output_losses(mesh, format, a)) {
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
  std::optional<MeshFormat> format;
  try {
    format = check_outputs(a);
  } catch (const FileError& e) {
    streams.err << "holefill: " << e.what() << "\n";
    return kWriteFailed;
  }
  Mesh mesh = load_and_warn(a.input, a.format, streams, a.options.threads);
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
                         : fill_holes(mesh, holes, prepared.islands, a.options, a.selection,
                                      progress ? &progress->progress() : nullptr);
  const std::string unwelded = undo_unused_welds(mesh, prepared.weld);
  if (!unwelded.empty()) streams.err << "holefill: " << a.input << ": " << unwelded << "\n";
  report.vertices_after = mesh.n_vertices();
  report.faces_after = mesh.n_faces();
  // Counted, not derived from the fills: undoing a weld can join two open loops into one.
  report.holes_after = count_holes(mesh);
  report.fills = &fills;

  const FillCounts counts = report_problems(fills, a.input, streams.err);
  const bool written = write_results(mesh, *format, report, a, streams);
  if (streams.verbosity != Verbosity::Quiet) {
    print_summary(fills, counts, report, stdout_carries_a_file(a) ? streams.err : streams.out);
  }
  if (!written) return kWriteFailed;
  if (counts.filled != fills.size()) return kSomeHolesNotFilled;
  return counts.intersecting ? kPatchesIntersect : kOk;
}

}  // namespace holefill::cli
