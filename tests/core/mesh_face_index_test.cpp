// MeshFaceIndex files only the faces near the holes, and more on demand: every lookup must still
// find exactly what a scan of all the faces (and the entries added since) finds.
#include "mesh_face_index.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "face_grid.h"
#include "patch_intersections.h"
#include "test_meshes.h"

namespace holefill::detail {
namespace {

struct Added {
  int id;
  Box box;
};

// The scan the index stands for: faces below `indexed` (not deleted) and added entries whose
// boxes overlap `box`, ascending, each once.
std::vector<int> scanned(const Mesh& mesh, int indexed, const std::vector<Added>& added,
                         const Box& box) {
  std::vector<int> ids;
  for (const auto f : mesh.faces()) {
    if (f.idx() < indexed && box_of(mesh, f).overlaps(box)) ids.push_back(f.idx());
  }
  for (const auto& a : added) {
    if (a.box.overlaps(box)) ids.push_back(a.id);
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

Box box_around(const Point& centre, double half) {
  Box box;
  box.add(centre - Point(half, half, half));
  box.add(centre + Point(half, half, half));
  return box;
}

// A wavy 40 x 40 grid (3,200 faces over [0, 1]^2) and lookups of every size, inside the regions,
// across their edges and far from them, before and after entries are added.
TEST(MeshFaceIndex, FindsWhatAScanOfAllFacesFinds) {
  Mesh mesh = testing::make_grid(40, [](double x, double y) { return 0.1 * std::sin(9 * x * y); });
  mesh.request_face_status();  // a library user's mesh with OpenMesh's flags, one face deleted
  mesh.request_edge_status();
  mesh.request_halfedge_status();
  mesh.delete_face(FaceHandle(5), false);  // a deleted face is not indexed
  const int indexed = static_cast<int>(mesh.n_faces());
  const std::vector<Box> regions{box_around({0.2, 0.2, 0.0}, 0.05),
                                 box_around({0.7, 0.4, 0.0}, 0.1)};
  MeshFaceIndex index(mesh, regions);
  std::vector<Added> added;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-0.2, 1.2), size(0.0, 0.3);
  for (int round = 0; round < 300; ++round) {
    if (round % 50 == 49) {  // a patch's face joins, as fill_holes adds them
      const auto v = mesh.add_vertex({coordinate(rng), coordinate(rng), 0.5});
      const auto w = mesh.add_vertex({coordinate(rng), coordinate(rng), 0.5});
      const auto u = mesh.add_vertex({coordinate(rng), coordinate(rng), -0.5});
      const FaceHandle f = mesh.add_face(v, w, u);
      added.push_back({f.idx(), box_of(mesh, f)});
      index.add(added.back().id, added.back().box);
    }
    const Box box = round % 3 == 0
                        ? box_around(regions[round % 2].low + Point(0.03, 0.04, 0.0), size(rng) / 8)
                        : box_around({coordinate(rng), coordinate(rng), 0.0}, size(rng));
    ASSERT_EQ(index.near(box), scanned(mesh, indexed, added, box)) << "lookup " << round;
  }
  // A box with no extent, one covering everything, the empty box and a NaN one.
  for (const Box& box : {box_around({0.5, 0.5, 0.0}, 0.0), box_around({0.5, 0.5, 0.0}, 1e6), Box{},
                         box_around({NAN, 0.5, 0.0}, 0.1)}) {
    EXPECT_EQ(index.near(box), scanned(mesh, indexed, added, box));
  }
}

// Regions far apart make a coarse grid too fine to allocate; huge coordinates make one
// impossible: the index then files more faces, never fewer.
TEST(MeshFaceIndex, ExactWithFarApartRegionsAndHugeCoordinates) {
  for (const double scale : {1.0, 1e300}) {
    Mesh mesh = testing::make_grid(20, [](double x, double y) { return x * y; });
    for (const auto v : mesh.vertices()) mesh.set_point(v, mesh.point(v) * scale);
    std::vector<Box> regions;
    for (int i = 0; i < 5; ++i) {
      regions.push_back(box_around(Point(0.2 * i, 0.1 * i, 0.0) * scale, 1e-7 * scale));
    }
    regions.push_back(box_around(Point(1e6, 0.0, 0.0) * std::min(scale, 1.0), 1e-7));
    const MeshFaceIndex index(mesh, regions);
    for (const Box& box : {regions[2], box_around(Point(0.5, 0.5, 0.25) * scale, 0.2 * scale),
                           box_around(Point(0.3, 0.6, 0.0) * scale, 0.01 * scale)}) {
      EXPECT_EQ(index.near(box), scanned(mesh, static_cast<int>(mesh.n_faces()), {}, box));
    }
  }
}

// Many small regions spread over the whole mesh (a scan with hundreds of small holes) file the
// faces that overlap them and no others: a coarse grid of marked cells filed most of the mesh.
TEST(MeshFaceIndex, FilesOnlyFacesOverlappingSpreadOutRegions) {
  const Mesh mesh =
      testing::make_grid(150, [](double x, double y) { return 0.05 * std::sin(7 * x + 5 * y); });
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coordinate(0.0, 1.0), half(0.002, 0.02);
  std::vector<Box> regions;
  for (int r = 0; r < 300; ++r) {
    regions.push_back(box_around({coordinate(rng), coordinate(rng), 0.0}, half(rng)));
  }
  std::size_t overlapping = 0;
  for (const auto f : mesh.faces()) {
    const Box box = box_of(mesh, f);
    overlapping += std::any_of(regions.begin(), regions.end(),
                               [&box](const Box& region) { return region.overlaps(box); });
  }
  const MeshFaceIndex index(mesh, regions);
  EXPECT_EQ(index.filed_faces(), overlapping);
  EXPECT_LT(overlapping, mesh.n_faces() / 4);
  for (const Box& region : regions) {
    ASSERT_EQ(index.near(region), scanned(mesh, static_cast<int>(mesh.n_faces()), {}, region));
  }
  EXPECT_EQ(index.filed_faces(), overlapping);  // lookups inside the regions file nothing more
}

// Filed on several threads (80,000 faces: two blocks), the index finds what a scan finds.
TEST(MeshFaceIndex, FiledOnThreeThreadsFindsWhatAScanFinds) {
  const Mesh mesh = testing::make_grid(200, [](double x, double y) { return 0.1 * x * y; });
  const std::vector<Box> regions{box_around(Point(0.2, 0.2, 0.0), 0.05),
                                 box_around(Point(0.7, 0.8, 0.0), 0.1)};
  const MeshFaceIndex index(mesh, regions, 3);
  for (const Box& box : {regions[0], regions[1], box_around(Point(0.72, 0.75, 0.054), 0.02)}) {
    const auto found = index.near(box);
    EXPECT_FALSE(found.empty());
    EXPECT_EQ(found, scanned(mesh, static_cast<int>(mesh.n_faces()), {}, box));
  }
}

// A view (one hole filled apart from the mesh) finds what its whole finds inside its region, and
// nothing, saying so, outside it; it records every box looked up.
TEST(MeshFaceIndex, AViewFindsWhatItsWholeFindsInsideItsRegionOnly) {
  const Mesh mesh = testing::make_grid(40, [](double x, double y) { return 0.1 * x * y; });
  const Box region = box_around(Point(0.5, 0.5, 0.0), 0.2);
  const MeshFaceIndex whole(mesh, {region, box_around(Point(0.1, 0.1, 0.0), 0.05)});
  const MeshFaceIndex view(whole, region);
  const Box inside = box_around(Point(0.45, 0.55, 0.0), 0.1);
  EXPECT_EQ(view.near(inside), scanned(mesh, static_cast<int>(mesh.n_faces()), {}, inside));
  EXPECT_FALSE(view.near(inside).empty());
  EXPECT_FALSE(view.looked_outside());
  const Box across = box_around(Point(0.68, 0.5, 0.0), 0.05);
  EXPECT_TRUE(view.near(across).empty());
  EXPECT_TRUE(view.looked_outside());
  EXPECT_TRUE(whole.near(across) == scanned(mesh, static_cast<int>(mesh.n_faces()), {}, across));
  Box both = inside;
  both.add(across);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_EQ(view.looked_up().low[axis], both.low[axis]);
    EXPECT_EQ(view.looked_up().high[axis], both.high[axis]);
  }
  EXPECT_EQ(&view.mesh(), &mesh);
}

// A patch of thousands of triangles (many blocks) over a grid of 20,000 faces (two blocks of
// faces to gather, several chunks of the grid's cells) checked on several threads gives the pairs
// of one thread, in the same order.
TEST(MeshFaceIndex, ALargePatchIsCheckedInBlocksWithTheOneThreadPairs) {
  const Mesh mesh = testing::make_grid(100, [](double x, double y) { return 0.05 * (x - y); });
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> at(0.0, 1.0), height(-0.1, 0.1);
  std::vector<std::array<Point, 3>> triangles;
  for (int t = 0; t < 9000; ++t) {
    const Point c(at(rng), at(rng), height(rng));
    triangles.push_back({c, c + Point(0.02, 0.0, height(rng)), c + Point(0.0, 0.02, height(rng))});
  }
  Box all;
  all.add(Point(-1, -1, -1));
  all.add(Point(2, 2, 1));
  MeshFaceIndex index(mesh, {all});
  const auto one = triangle_intersections(mesh, triangles, nullptr, &index, true);
  ASSERT_GT(one.size(), 1000u);
  for (const unsigned threads : {2u, 3u, 1000u}) {
    index.set_threads(threads);
    const auto many = triangle_intersections(mesh, triangles, nullptr, &index, true);
    ASSERT_EQ(many.size(), one.size()) << threads << " threads";
    for (std::size_t p = 0; p < one.size(); ++p) {
      EXPECT_EQ(many[p].triangle, one[p].triangle);
      EXPECT_EQ(many[p].other_triangle, one[p].other_triangle);
      EXPECT_EQ(many[p].other_face, one[p].other_face);
    }
  }
}

}  // namespace
}  // namespace holefill::detail
