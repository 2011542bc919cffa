// `holefill info MESH`: counts and a table of the holes (or the same as JSON).
#include <iomanip>
#include <ostream>

#include "commands.h"
#include "holefill/holes.h"
#include "holefill/stats.h"
#include "mesh_input.h"
#include "report.h"
#include "table.h"

namespace holefill::cli {

int run_info(const InfoArguments& a, const Streams& streams) {
  Mesh mesh = load_and_warn(a.input, a.format, streams);
  const PreparedMesh prepared = prepare_mesh(mesh, a.preparation, a.input, streams.err);
  const auto& holes = prepared.holes;
  std::ostream& out = streams.out;
  if (a.json) {
    out << json_info(a.input, mesh, prepared);
    return kOk;
  }
  out << a.input << ": " << mesh.n_vertices() << " vertices, " << mesh.n_faces() << " faces, "
      << connected_components(mesh) << " components, " << holes.size() << " holes\n";
  if (holes.empty()) return kOk;
  // A space between columns whatever the widths: huge values widen a row, never merge cells.
  out << "  hole  boundary_edges   perimeter  note\n";
  for (std::size_t i = 0; i < holes.size(); ++i) {
    const Hole& hole = holes[i];
    out << std::setw(6) << hole.id << ' ' << std::setw(15) << hole.size() << ' ' << std::setw(11)
        << format("%.6g", hole.perimeter) << "  " << loop_note(hole, prepared.classes[i]) << "\n";
  }
  return kOk;
}

}  // namespace holefill::cli
