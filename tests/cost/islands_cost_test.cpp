// Island detection costs time about linear in the loops' lengths (issue 32, #4): every point of
// a loop was tested against every edge of the hole around it, so a ring with two 200,000-edge
// wavy loops took 218 s in `holefill info` and a 65,535-edge island in a 65,535-edge hole 155 s
// (1.3 and 1.2 s now). Sized so that the old way runs past this suite's per-test limit.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "holefill/holes.h"
#include "holefill/islands.h"

namespace holefill::testing {
namespace {

// An annulus of n quads (2n triangles) between radii r0 < r1, the radius waving by `wave` 50
// times around.
void add_ring(Mesh& mesh, int n, double r0, double r1, double wave) {
  std::vector<VertexHandle> inner, outer;
  for (const double r : {r0, r1}) {
    for (int i = 0; i < n; ++i) {
      const double a = 2.0 * std::numbers::pi * i / n, w = 1.0 + wave * std::sin(50.0 * a);
      (r == r0 ? inner : outer)
          .push_back(mesh.add_vertex(Point(r * w * std::cos(a), r * w * std::sin(a), 0.0)));
    }
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    mesh.add_face(inner[i], outer[i], outer[j]);
    mesh.add_face(inner[i], outer[j], inner[j]);
  }
}

// A fan of n triangles around the origin: a disk of radius r.
void add_disk(Mesh& mesh, int n, double r) {
  const VertexHandle centre = mesh.add_vertex(Point(0.0, 0.0, 0.0));
  std::vector<VertexHandle> rim;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n;
    rim.push_back(mesh.add_vertex(Point(r * std::cos(a), r * std::sin(a), 0.0)));
  }
  for (int i = 0; i < n; ++i) mesh.add_face(centre, rim[i], rim[(i + 1) % n]);
}

TEST(IslandsCost, ARingsTwoLongLoopsAreNoIslandsOfEachOther) {
  Mesh mesh;
  add_ring(mesh, 300000, 1.0, 1.5, 0.02);
  const auto holes = find_holes(mesh);
  ASSERT_EQ(holes.size(), 2u);
  const IslandMap map = find_islands(mesh, holes);
  for (int h = 0; h < 2; ++h) {
    EXPECT_FALSE(map.has_islands(h));
    EXPECT_EQ(map.outer[h], -1);
    EXPECT_EQ(map.note[h], "");
  }
}

TEST(IslandsCost, ALongIslandInALongHoleIsFound) {
  constexpr int kEdges = 65535;
  Mesh mesh;
  add_ring(mesh, kEdges, 2.0, 3.0, 0.0);
  add_disk(mesh, kEdges, 1.0);
  const auto holes = find_holes(mesh);
  ASSERT_EQ(holes.size(), 3u);
  // The ring's inner loop is the hole, the disk's rim its island; the ring's outer rim holds the
  // disk too, but runs the same way round as it.
  int hole = -1, island = -1;
  for (const auto& h : holes) {
    const double r = (mesh.point(h.vertices[0])).norm();
    if (std::abs(r - 2.0) < 1e-9) hole = h.id;
    if (std::abs(r - 1.0) < 1e-9) island = h.id;
  }
  ASSERT_GE(hole, 0);
  ASSERT_GE(island, 0);
  const IslandMap map = find_islands(mesh, holes);
  EXPECT_EQ(map.islands[hole], std::vector<int>{island});
  EXPECT_EQ(map.outer[island], hole);
  for (const auto& note : map.note) EXPECT_EQ(note, "");

  // Moved onto the hole's loop the island touches it: a note on both, found as quickly.
  Mesh touching;
  add_ring(touching, kEdges, 2.0, 3.0, 0.0);
  add_disk(touching, kEdges, 2.0 - 1e-6);
  const auto loops = find_holes(touching);
  const IslandMap touched = find_islands(touching, loops);
  std::size_t problems = 0;
  for (const auto& note : touched.note) {
    problems += note.find("touches its boundary") != std::string::npos;
  }
  EXPECT_EQ(problems, 2u);
}

}  // namespace
}  // namespace holefill::testing
