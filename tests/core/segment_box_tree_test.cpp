// SegmentBoxTree finds every box a segment meets (checked against points sampled along the
// segment) and only boxes near it; the chords of a hole through the mesh found through it are
// those found by testing every face.
#include "segment_box_tree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <random>
#include <set>
#include <vector>

#include "holefill/holes.h"
#include "patch_intersections.h"
#include "test_meshes.h"
#include "triangle_intersection.h"

namespace holefill::detail {
namespace {

bool contains(const Box& box, const Point& p) {
  for (int axis = 0; axis < 3; ++axis) {
    if (!(box.low[axis] <= p[axis] && p[axis] <= box.high[axis])) return false;
  }
  return true;
}

std::set<int> visited_along(const SegmentBoxTree& tree, const Point& a, const Point& b) {
  std::set<int> ids;
  const bool stopped = tree.any_along(a, b, [&](int id) {
    ids.insert(id);
    return false;
  });
  EXPECT_FALSE(stopped);
  return ids;
}

TEST(SegmentBoxTree, VisitsEveryBoxTheSegmentPassesThroughAndOnlyBoxesNearIt) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> at(0.0, 10.0), size(0.0, 0.6);
  std::vector<std::pair<int, Box>> boxes;
  for (int id = 0; id < 2000; ++id) {
    Box box;
    const Point low(at(rng), at(rng), at(rng));
    box.add(low);
    box.add(low + Point(size(rng), size(rng), id % 7 == 0 ? 0.0 : size(rng)));  // some flat
    boxes.emplace_back(id, box);
  }
  Box odd;
  odd.add(Point(1.0, 1.0, 1.0));
  odd.low[0] = NAN;
  boxes.emplace_back(5000, odd);  // a NaN box: always visited
  const SegmentBoxTree tree(boxes);
  for (int round = 0; round < 300; ++round) {
    const Point a(at(rng), at(rng), at(rng));
    // Long and short segments, and some along an axis (a zero direction component).
    Point b = round % 3 == 0 ? a + Point(size(rng), size(rng), size(rng))
                             : Point(at(rng), at(rng), at(rng));
    if (round % 5 == 0) b = Point(a[0], a[1], at(rng));
    const std::set<int> visited = visited_along(tree, a, b);
    EXPECT_TRUE(visited.count(5000));
    Box reach;
    reach.add(a);
    reach.add(b);
    reach.grow(1e-6);
    for (const auto& [id, box] : boxes) {
      if (id == 5000) continue;
      if (!box.overlaps(reach)) {
        EXPECT_FALSE(visited.count(id)) << "round " << round << ", box " << id;
        continue;
      }
      bool crossed = false;
      for (int s = 0; s <= 1000 && !crossed; ++s) {
        crossed = contains(box, a + (b - a) * (s / 1000.0));
      }
      if (crossed) {
        EXPECT_TRUE(visited.count(id)) << "round " << round << ", box " << id;
      }
    }
  }
  // any_along stops at the first box visit accepts.
  int visits = 0;
  EXPECT_TRUE(
      tree.any_along(Point(0, 0, 0), Point(10, 10, 10), [&](int) { return ++visits == 3; }));
  EXPECT_EQ(visits, 3);
}

// A hole with a staircase border (the faces of a wavy grid whose centroids lie in a disc are
// cut out): many chords between its corners run over the steps, through the mesh.
TEST(ChordsThroughMesh, AreTheChordsThatEnterSomeFaceOfTheMesh) {
  const Mesh mesh = testing::without_faces(
      testing::make_grid(
          24, [](double x, double y) { return 0.05 * std::sin(6 * x) * std::cos(5 * y); }),
      [](const Point& c) { return std::hypot(c[0] - 0.5, c[1] - 0.5) < 0.3; });
  const auto holes = find_holes(mesh);
  // The round hole is the smaller loop (the grid's outer border has the same centroid).
  const auto inner = std::min_element(
      holes.begin(), holes.end(), [](const Hole& a, const Hole& b) { return a.size() < b.size(); });
  ASSERT_NE(inner, holes.end());
  std::vector<Point> points;
  for (const auto v : inner->vertices) points.push_back(mesh.point(v));
  const int n = static_cast<int>(points.size());

  std::vector<std::pair<int, int>> expected;
  for (int i = 0; i < n; ++i) {
    for (int k = i + 2; k < n; ++k) {
      if (i == 0 && k == n - 1) continue;
      for (const auto f : mesh.faces()) {
        auto fv = mesh.cfv_iter(f);
        const auto triangle =
            triangle_from({mesh.point(*fv), mesh.point(*++fv), mesh.point(*++fv)});
        if (triangle && segment_enters_triangle(points[i], points[k], *triangle)) {
          expected.emplace_back(i, k);
          break;
        }
      }
    }
  }
  ASSERT_GT(expected.size(), 10u);  // the case is one where chords do pass through the mesh
  EXPECT_EQ(chords_through_mesh(mesh, points, nullptr), expected);
  Box reach;
  for (const auto& p : points) reach.add(p);
  const MeshFaceIndex around(mesh, {reach});
  EXPECT_EQ(chords_through_mesh(mesh, points, &around), expected);

  // Among given chords: every other one, and neighbours and the closing edge, never reported.
  std::vector<std::pair<int, int>> among{{0, 1}, {0, n - 1}};
  for (int i = 0; i < n; ++i) {
    for (int k = i + 2; k < n; ++k) {
      if ((i + k) % 2 == 0) among.emplace_back(i, k);
    }
  }
  std::sort(among.begin(), among.end());
  std::vector<std::pair<int, int>> expected_among;
  std::copy_if(expected.begin(), expected.end(), std::back_inserter(expected_among),
               [](const auto& chord) { return (chord.first + chord.second) % 2 == 0; });
  ASSERT_GT(expected_among.size(), 3u);
  EXPECT_EQ(chords_through_mesh(mesh, points, &around, &among), expected_among);
  EXPECT_EQ(chords_through_mesh(mesh, points, nullptr, &among), expected_among);
}

}  // namespace
}  // namespace holefill::detail
