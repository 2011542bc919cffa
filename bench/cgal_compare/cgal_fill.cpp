// holefill-cgal-fill: CGAL's side of bench/NOTEBOOK.md's "Big meshes, whole process". Reads a PLY
// into a CGAL Surface_mesh, fills every border cycle with
// CGAL::Polygon_mesh_processing::triangulate_and_refine_hole (default parameters) and writes a
// PLY, so that `/usr/bin/time` measures what `holefill fill` does: read, fill, write.
//
//   holefill-cgal-fill IN.ply OUT.ply [--repair] [--binary]
//
// By default the file is read straight into the Surface_mesh (CGAL::IO::read_PLY: no repair, a
// non-manifold file is refused); --repair reads it as `holefill` does, as a polygon soup that is
// repaired and oriented before the mesh is built (CGAL::Polygon_mesh_processing::IO::
// read_polygon_mesh). The output is ASCII with 17 significant digits (round-trip exact, as
// `holefill fill` writes a PLY) unless --binary. Phase times go to standard error.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/io.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

class PhaseClock {
 public:
  void report(const char* phase) {
    const auto now = std::chrono::steady_clock::now();
    std::fprintf(stderr, "%s: %.3f s\n", phase,
                 std::chrono::duration<double>(now - start_).count());
    start_ = now;
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

bool read_mesh(const char* path, bool repair, Mesh& mesh) {
  if (repair) return PMP::IO::read_polygon_mesh(path, mesh);
  std::ifstream in(path, std::ios::binary);
  return in && CGAL::IO::read_PLY(in, mesh);
}

}  // namespace

int main(int argc, char** argv) {
  bool repair = false, binary = false, usage = argc < 3;
  for (int i = 3; i < argc; ++i) {
    const std::string_view option = argv[i];
    repair |= option == "--repair";
    binary |= option == "--binary";
    usage |= option != "--repair" && option != "--binary";
  }
  if (usage) {
    std::cerr << "usage: holefill-cgal-fill IN.ply OUT.ply [--repair] [--binary]\n";
    return 2;
  }
  PhaseClock clock;
  Mesh mesh;
  if (!read_mesh(argv[1], repair, mesh)) {
    std::cerr << argv[1] << ": not read as a PLY surface mesh\n";
    return 3;
  }
  clock.report("read");

  std::vector<Mesh::Halfedge_index> cycles;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  std::size_t new_faces = 0, new_vertices = 0;
  for (const Mesh::Halfedge_index border : cycles) {
    std::vector<Mesh::Face_index> faces;
    std::vector<Mesh::Vertex_index> vertices;
    PMP::triangulate_and_refine_hole(mesh, border, std::back_inserter(faces),
                                     std::back_inserter(vertices));
    new_faces += faces.size();
    new_vertices += vertices.size();
  }
  clock.report("fill");
  std::fprintf(stderr, "%zu holes, %zu faces and %zu vertices added\n", cycles.size(), new_faces,
               new_vertices);

  std::ofstream out(argv[2], std::ios::binary);
  if (binary) {
    CGAL::IO::set_binary_mode(out);
  }
  if (!CGAL::IO::write_PLY(out, mesh, CGAL::parameters::stream_precision(17)) || !out.flush()) {
    std::cerr << argv[2] << ": not written\n";
    return 4;
  }
  clock.report("write");
  return 0;
}
