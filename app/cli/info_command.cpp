// `holefill info MESH`: counts and a table of the holes.
#include <iomanip>
#include <ostream>

#include "commands.h"
#include "holefill/holes.h"
#include "holefill/io.h"
#include "holefill/stats.h"
#include "mesh_input.h"
#include "table.h"

namespace holefill::cli {

int run_info(const std::string& input, const Streams& streams) {
  const Mesh mesh = load_and_warn(input, streams);
  const auto holes = find_holes(mesh);
  std::ostream& out = streams.out;
  out << input << ": " << mesh.n_vertices() << " vertices, " << mesh.n_faces() << " faces, "
      << connected_components(mesh) << " components, " << holes.size() << " holes\n";
  if (holes.empty()) return kOk;
  out << "  hole  boundary_edges   perimeter  note\n";
  for (const auto& hole : holes) {
    out << std::setw(6) << hole.id << std::setw(16) << hole.size() << std::setw(12)
        << format("%.6g", hole.perimeter) << "  " << (hole.pinched ? "pinched" : "") << "\n";
  }
  return kOk;
}

}  // namespace holefill::cli
