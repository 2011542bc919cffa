// `holefill info MESH`: counts and a table of the holes with their islands (or the same as JSON).
#include <iomanip>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "commands.h"
#include "holefill/holes.h"
#include "holefill/islands.h"
#include "holefill/stats.h"
#include "mesh_input.h"
#include "report.h"
#include "table.h"

namespace holefill::cli {
namespace {

// "pinched", "islands 1,2", "island of 0", and "see below" when the hole has a problem.
std::string hole_note(const Hole& hole, const IslandMap& islands) {
  std::vector<std::string> notes;
  if (hole.pinched) notes.push_back("pinched");
  if (islands.has_islands(hole.id)) notes.push_back("islands " + id_list(islands.islands[hole.id]));
  if (islands.outer[hole.id] >= 0) {
    notes.push_back("island of " + std::to_string(islands.outer[hole.id]));
  }
  if (!islands.problem[hole.id].empty()) notes.push_back("see below");
  std::string note;
  for (const auto& text : notes) {
    if (!note.empty()) note += ", ";
    note += text;
  }
  return note;
}

}  // namespace

int run_info(const InfoArguments& a, const Streams& streams) {
  const Mesh mesh = load_and_warn(a.input, a.format, streams);
  const auto holes = find_holes(mesh);
  std::ostream& out = streams.out;
  if (a.json) {
    out << json_info(a.input, mesh, holes);
    return kOk;
  }
  out << a.input << ": " << mesh.n_vertices() << " vertices, " << mesh.n_faces() << " faces, "
      << connected_components(mesh) << " components, " << holes.size() << " holes\n";
  if (holes.empty()) return kOk;
  // A space between columns whatever the widths: huge values widen a row, never merge cells.
  const IslandMap islands = find_islands(mesh, holes);
  out << "  hole  boundary_edges   perimeter  note\n";
  for (const auto& hole : holes) {
    out << std::setw(6) << hole.id << ' ' << std::setw(15) << hole.size() << ' ' << std::setw(11)
        << format("%.6g", hole.perimeter) << "  " << hole_note(hole, islands) << "\n";
  }
  std::set<std::string> problems(islands.problem.begin(), islands.problem.end());
  problems.erase("");
  for (const auto& problem : problems) out << "  not fillable as is: " << problem << "\n";
  return kOk;
}

}  // namespace holefill::cli
