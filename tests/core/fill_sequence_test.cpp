// A FillSequence makes exactly what advance_joined() makes step by step, in whatever order the
// steps come (hole by hole, or going back and forth, when it falls back to scanning the mesh),
// including where the self-intersection checks find something.
#include "holefill/fill_sequence.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "holefill/holes.h"
#include "test_meshes.h"

namespace holefill {
namespace {

// A wavy sheet with round holes, and a small upright square standing in one of them, which the
// patch across that hole would cut (its own border is a loop too).
Mesh sheet_with_holes_and_a_fin() {
  const Mesh sheet =
      testing::make_grid(30, [](double x, double y) { return 0.05 * std::sin(6 * x + 4 * y); });
  const std::vector<Point> centres{{0.25, 0.25, 0}, {0.7, 0.3, 0}, {0.3, 0.72, 0}, {0.72, 0.7, 0}};
  Mesh mesh = testing::without_faces(sheet, [&](const Point& c) {
    for (const Point& centre : centres) {
      if (std::hypot(c[0] - centre[0], c[1] - centre[1]) < 0.09) return true;
    }
    return false;
  });
  const VertexHandle a = mesh.add_vertex({0.22, 0.25, -0.1}),
                     b = mesh.add_vertex({0.28, 0.25, -0.1});
  const VertexHandle c = mesh.add_vertex({0.28, 0.25, 0.1}), d = mesh.add_vertex({0.22, 0.25, 0.1});
  mesh.add_face(a, b, c);
  mesh.add_face(a, c, d);
  return mesh;
}

// Each step: the hole's id (its loop alone).
using Steps = std::vector<int>;

std::pair<Mesh, std::vector<HoleFill>> run(const Mesh& start, const std::vector<Hole>& holes,
                                           const Steps& steps, bool in_sequence) {
  Mesh mesh = start;
  std::vector<HoleFill> fills(holes.size());
  std::vector<std::vector<const Hole*>> groups;
  for (const Hole& hole : holes) groups.push_back({&hole});
  FillSequence sequence(mesh, groups);
  for (const int id : steps) {
    const std::vector<const Hole*> loops{&holes[id]};
    if (in_sequence) {
      sequence.step(loops, fills[id], FillOptions{});
    } else {
      advance_joined(mesh, loops, fills[id], FillOptions{});
    }
  }
  return {std::move(mesh), std::move(fills)};
}

void expect_same(const std::pair<Mesh, std::vector<HoleFill>>& got,
                 const std::pair<Mesh, std::vector<HoleFill>>& expected) {
  const Mesh &a = got.first, &b = expected.first;
  ASSERT_EQ(a.n_vertices(), b.n_vertices());
  ASSERT_EQ(a.n_faces(), b.n_faces());
  for (const auto v : a.vertices()) EXPECT_EQ(a.point(v), b.point(v)) << "vertex " << v.idx();
  for (const auto f : a.faces()) {
    std::vector<int> corners_a, corners_b;
    for (const auto v : a.fv_range(f)) corners_a.push_back(v.idx());
    for (const auto v : b.fv_range(FaceHandle(f.idx()))) corners_b.push_back(v.idx());
    EXPECT_EQ(corners_a, corners_b) << "face " << f.idx();
  }
  for (std::size_t h = 0; h < got.second.size(); ++h) {
    const HoleFill &x = got.second[h], &y = expected.second[h];
    EXPECT_EQ(x.stage(), y.stage()) << "hole " << h;
    EXPECT_EQ(x.failure, y.failure) << "hole " << h;
    EXPECT_EQ(x.self_intersections, y.self_intersections) << "hole " << h;
    EXPECT_EQ(x.avoidance.first_pairs, y.avoidance.first_pairs) << "hole " << h;
    EXPECT_EQ(x.refinement_note, y.refinement_note) << "hole " << h;
    EXPECT_EQ(x.smoothing_note, y.smoothing_note) << "hole " << h;
    EXPECT_EQ(x.stats.new_vertices, y.stats.new_vertices) << "hole " << h;
  }
}

TEST(FillSequence, MakesWhatAdvanceMakesHoleByHoleAndBackAndForth) {
  const Mesh start = sheet_with_holes_and_a_fin();
  const std::vector<Hole> holes = find_holes(start);
  ASSERT_GE(holes.size(), 6u);  // the sheet's border, four holes, the fin's border
  Steps hole_by_hole, back_and_forth;
  for (int id = 0; id < static_cast<int>(holes.size()); ++id) {
    for (int stage = 0; stage < 3; ++stage) hole_by_hole.push_back(id);
  }
  for (int stage = 0; stage < 3; ++stage) {
    for (int id = 0; id < static_cast<int>(holes.size()); ++id) back_and_forth.push_back(id);
  }
  for (const Steps& steps : {hole_by_hole, back_and_forth}) {
    const auto expected = run(start, holes, steps, false);
    expect_same(run(start, holes, steps, true), expected);
    // The checks mattered: the fin's hole had to avoid it.
    std::size_t pairs = 0;
    for (const HoleFill& fill : expected.second) pairs += fill.avoidance.first_pairs;
    EXPECT_GT(pairs, 0u);
  }
}

}  // namespace
}  // namespace holefill
