// Fills the open face of a tetrahedron through the installed holefill::core; exits 0 when the
// hole is gone and the version header matches the one the test expects.
#include <cstdio>
#include <cstring>

#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/version.h"

int main(int argc, char** argv) {
  if (argc != 2 || std::strcmp(argv[1], HOLEFILL_VERSION) != 0) {
    std::fprintf(stderr, "installed version %s, expected %s\n", HOLEFILL_VERSION,
                 argc == 2 ? argv[1] : "?");
    return 1;
  }
  holefill::Mesh mesh;
  const auto a = mesh.add_vertex({0, 0, 0}), b = mesh.add_vertex({1, 0, 0}),
             c = mesh.add_vertex({0, 1, 0}), d = mesh.add_vertex({0, 0, 1});
  mesh.add_face(a, c, b);
  mesh.add_face(a, b, d);
  mesh.add_face(b, c, d);
  const auto holes = holefill::find_holes(mesh);
  const auto fills = holefill::fill_holes(mesh, holes, holefill::FillOptions{});
  const bool closed = holes.size() == 1 && fills.size() == 1 && !fills[0].failed() &&
                      holefill::find_holes(mesh).empty();
  std::printf("%s\n", closed ? "filled" : "not filled");
  return closed ? 0 : 1;
}
