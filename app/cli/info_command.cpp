// `holefill info MESH`: counts and a table of the holes with their islands (or the same as JSON).
#include <iomanip>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "commands.h"
#include "holefill/features.h"
#include "holefill/holes.h"
#include "holefill/islands.h"
#include "holefill/stats.h"
#include "mesh_input.h"
#include "report.h"
#include "table.h"

namespace holefill::cli {
namespace {

// "islands 1,2", "island of 0", and "see below" when a doubtful island is filled apart (pinches
// are in the loop's own note).
std::string island_note(const Hole& hole, const IslandMap& islands) {
  std::string note;
  auto add = [&note](const std::string& part) { note += (note.empty() ? "" : ", ") + part; };
  if (islands.has_islands(hole.id)) add("islands " + id_list(islands.islands[hole.id]));
  if (islands.outer[hole.id] >= 0) add("island of " + std::to_string(islands.outer[hole.id]));
  if (!islands.note[hole.id].empty()) add("see below");
  return note;
}

std::string joined_note(const std::string& first, const std::string& second) {
  return first.empty() || second.empty() ? first + second : first + ", " + second;
}

}  // namespace

int run_info(const InfoArguments& a, const Streams& streams) {
  Mesh mesh = load_and_warn(a.input, a.format, streams, a.threads);
  PreparationChoice choice = a.preparation;
  choice.islands.detect = a.islands == "on";
  choice.threads = a.threads;
  const PreparedMesh prepared = prepare_mesh(mesh, choice, a.input, streams.err);
  const auto& holes = prepared.holes;
  std::ostream& out = streams.out;
  if (a.json) {
    out << json_info(a.input, mesh, prepared, a.features);
    return kOk;
  }
  const SurfaceCounts counts = surface_counts(mesh);
  out << a.input << ": " << mesh.n_vertices() << " vertices";
  if (counts.unused_vertices > 0) out << " (" << counts.unused_vertices << " used by no face)";
  out << ", " << mesh.n_faces() << " faces, " << counts.components << " components, "
      << holes.size() << " holes\n";
  if (holes.empty()) return kOk;
  // A space between columns whatever the widths: huge values widen a row, never merge cells.
  const IslandMap& islands = prepared.islands;
  out << "  hole  boundary_edges   perimeter  note\n";
  for (std::size_t i = 0; i < holes.size(); ++i) {
    const Hole& hole = holes[i];
    out << std::setw(6) << hole.id << ' ' << std::setw(15) << hole.size() << ' ' << std::setw(11)
        << format("%.6g", hole.perimeter) << "  "
        << joined_note(
               joined_note(loop_note(hole, prepared.classes[i]), island_note(hole, islands)),
               features_summary(find_hole_features(mesh, hole, a.features)))
        << "\n";
  }
  std::set<std::string> notes(islands.note.begin(), islands.note.end());
  notes.erase("");
  for (const auto& note : notes) out << "  filled apart: " << note << "\n";
  return kOk;
}

}  // namespace holefill::cli
