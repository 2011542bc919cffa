// The loader's direct construction of the half-edges (core/src/io/mesh_from_triangles.h) keeps
// its contract: the edge uses are those of a plain sort by edge then triangle, and the assembled
// mesh numbers its edges and links its faces as the contract says.
#include <OpenMesh/Tools/Utils/MeshCheckerT.hh>
#include <algorithm>
#include <cstring>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <stdexcept>
#include <tuple>

#include "dirty_meshes.h"
#include "holefill/holes.h"
#include "holefill/obj_attributes.h"
#include "io/mesh_from_triangles.h"
#include "io/readers.h"
#include "io/repair_checks.h"
#include "io/soup_to_mesh.h"
#include "io/two_threads.h"
#include "mesh_room.h"
#include "test_meshes.h"

namespace holefill::testing {
namespace {

// The uses in the order the contract gives: every triangle's three edges as (smaller, larger,
// triangle, forward), sorted with a comparison sort.
using UseTuple = std::tuple<int, int, int, bool>;
std::vector<UseTuple> sorted_edge_uses(const std::vector<io::Triangle>& triangles) {
  std::vector<UseTuple> uses;
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
    for (int c = 0; c < 3; ++c) {
      const int a = triangles[t][c], b = triangles[t][(c + 1) % 3];
      uses.emplace_back(std::min(a, b), std::max(a, b), t, a < b);
    }
  }
  std::sort(uses.begin(), uses.end());
  return uses;
}

TEST(MeshAssembly, EdgeUsesAreThoseOfSortingByEdgeThenTriangle) {
  std::mt19937 rng(7);
  // Few vertices: edges with many triangles in both directions; then a hub with 300 edges (a
  // vertex run far longer than the insertion sort handles).
  std::uniform_int_distribution<int> few(0, 11);
  std::vector<io::Triangle> triangles;
  while (triangles.size() < 400) {
    const io::Triangle t{few(rng), few(rng), few(rng)};
    if (t[0] != t[1] && t[1] != t[2] && t[2] != t[0]) triangles.push_back(t);
  }
  std::uniform_int_distribution<int> many(1, 300);
  for (int i = 0; i < 600; ++i) {
    const int a = many(rng), b = a % 300 + 1;
    triangles.push_back(i % 2 ? io::Triangle{0, a, b} : io::Triangle{b, 0, a});
  }
  const auto expected = sorted_edge_uses(triangles);
  std::set<std::pair<int, int>> distinct;
  for (const auto& [a, b, t, forward] : expected) distinct.emplace(a, b);
  // Made in blocks of triangles on several threads, up to more threads than triangles.
  for (const unsigned threads : {1u, 2u, 3u, 2000u}) {
    SCOPED_TRACE(threads);
    const io::EdgeUses uses(triangles, threads);
    std::vector<UseTuple> listed;
    std::size_t edges = 0;
    uses.for_each_edge([&](int smaller, std::size_t first, std::size_t last) {
      ++edges;
      EXPECT_GE(uses.start(static_cast<std::size_t>(smaller) + 1), last);
      for (std::size_t k = first; k < last; ++k) {
        EXPECT_EQ(uses[k].larger(), uses[first].larger());
        listed.emplace_back(smaller, uses[k].larger(), uses[k].triangle(), uses[k].forward());
      }
    });
    EXPECT_EQ(listed, expected);
    EXPECT_EQ(edges, distinct.size());
  }
}

// The checks that let the repairs skip their walks say what the soups hold, on any number of
// threads (more than the edges too): one closed tetrahedron, two touching at a vertex (two closed
// fans there), a bowtie (two open fans), a strip, a flipped neighbour, a fin (three triangles on
// an edge), a duplicate triangle.
TEST(MeshAssembly, RepairChecksFindWhatTheRepairsWouldRepair) {
  using T = std::vector<io::Triangle>;
  const T tetra = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}};
  T two_tetras = tetra;
  for (const auto& t : tetra) {
    two_tetras.push_back({t[0] ? t[0] + 3 : 0, t[1] ? t[1] + 3 : 0, t[2] ? t[2] + 3 : 0});
  }
  const T bowtie = {{0, 1, 2}, {0, 3, 4}}, strip = {{0, 1, 2}, {2, 1, 3}, {2, 3, 4}};
  const T flipped = {{0, 1, 2}, {1, 2, 3}}, fin = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  // A duplicate (the same corners in the same cyclic order) always makes a non-manifold edge,
  // which is why loading looks for duplicates only then; the same corners the other way round
  // are two sides of a closed surface.
  const T duplicate = {{0, 1, 2}, {1, 2, 0}}, two_sided = {{0, 1, 2}, {0, 2, 1}};
  struct Case {
    const char* name;
    T triangles;
    bool same_way, non_manifold, several_fans;
  };
  const Case cases[] = {{"tetrahedron", tetra, false, false, false},
                        {"two tetrahedra at a vertex", two_tetras, false, false, true},
                        {"bowtie", bowtie, false, false, true},
                        {"strip", strip, false, false, false},
                        {"flipped neighbour", flipped, true, true, false},
                        {"fin", fin, false, true, false},
                        {"duplicate", duplicate, true, true, false},
                        {"two-sided triangle", two_sided, false, false, false}};
  for (const auto& c : cases) {
    for (const unsigned threads : {1u, 2u, 3u, 64u}) {
      SCOPED_TRACE(std::string(c.name) + ", threads " + std::to_string(threads));
      const io::EdgeUses uses(c.triangles, threads);
      EXPECT_EQ(io::any_edge_run_the_same_way(uses, threads), c.same_way);
      EXPECT_EQ(io::any_non_manifold_edge(uses, threads), c.non_manifold);
      if (!c.non_manifold) {
        EXPECT_EQ(io::any_vertex_with_several_fans(c.triangles, uses, threads), c.several_fans);
      }
    }
  }
}

// The mesh assemble makes follows its contract, checked against the triangles themselves: the
// edges in sorted order, each edge's halfedge 2 e in its lowest triangle, every face's corners
// in its triangle's order from its first, and each vertex's halfedge leaving it in the last
// triangle using it (or on a boundary). On grids whose triangles come shuffled, their corners
// rotated and their vertices renumbered at random, so that every rank of first corner and every
// order of a face's halfedges occurs.
TEST(MeshAssembly, AssembledMeshNumbersEdgesAndLinksFacesAsItsContractSays) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    std::mt19937 rng(seed);
    const Mesh grid =
        make_grid(9 + static_cast<int>(seed), [](double x, double y) { return 0.1 * x * y; });
    std::vector<int> renumbered(grid.n_vertices());
    std::iota(renumbered.begin(), renumbered.end(), 0);
    std::shuffle(renumbered.begin(), renumbered.end(), rng);
    std::vector<Point> positions(grid.n_vertices());
    for (const auto v : grid.vertices()) positions[renumbered[v.idx()]] = grid.point(v);
    std::vector<io::Triangle> triangles;
    for (const auto f : grid.faces()) {
      io::Triangle t;
      int c = 0;
      for (const auto v : grid.fv_range(f)) t[c++] = renumbered[v.idx()];
      std::rotate(t.begin(), t.begin() + std::uniform_int_distribution<int>(0, 2)(rng), t.end());
      triangles.push_back(t);
    }
    std::shuffle(triangles.begin(), triangles.end(), rng);
    LoadReport report;
    const Mesh mesh = io::assemble(positions, triangles, std::vector<char>(triangles.size(), 0),
                                   positions.size(), report, nullptr);
    ASSERT_TRUE(OpenMesh::Utils::MeshCheckerT<Mesh>(mesh).check());

    std::map<std::pair<int, int>, int> lowest;  // edge -> its lowest triangle
    for (int t = static_cast<int>(triangles.size()) - 1; t >= 0; --t) {
      for (int c = 0; c < 3; ++c) {
        const int a = triangles[t][c], b = triangles[t][(c + 1) % 3];
        lowest[{std::min(a, b), std::max(a, b)}] = t;
      }
    }
    ASSERT_EQ(mesh.n_edges(), lowest.size());
    int e = 0;
    for (const auto& [edge, t] : lowest) {
      const HalfedgeHandle h(2 * e++);
      EXPECT_EQ(mesh.face_handle(h).idx(), t);
      const std::pair ends{mesh.from_vertex_handle(h).idx(), mesh.to_vertex_handle(h).idx()};
      EXPECT_TRUE((ends == edge || ends == std::pair{edge.second, edge.first}));
    }
    std::vector<int> last_triangle(positions.size(), -1);
    for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
      std::vector<int> corners;
      for (const auto v : mesh.fv_range(FaceHandle(t))) corners.push_back(v.idx());
      EXPECT_EQ(corners, std::vector<int>(triangles[t].begin(), triangles[t].end()));
      for (const int v : triangles[t]) last_triangle[v] = t;
    }
    for (const auto v : mesh.vertices()) {
      const HalfedgeHandle out = mesh.halfedge_handle(v);
      EXPECT_EQ(mesh.from_vertex_handle(out), v);
      if (mesh.is_boundary(v)) {
        EXPECT_TRUE(mesh.is_boundary(out));
      } else {
        EXPECT_EQ(mesh.face_handle(out).idx(), last_triangle[v.idx()]);
      }
    }
  }
}
}  // namespace
}  // namespace holefill::testing
