// fill_holes on any number of threads (FillOptions::threads) gives the same mesh and the same
// fills as on one: the holes are planned and filled apart from the mesh in parallel but spliced in
// order, and each dynamic program's result does not depend on its threads. The patches made
// apart are the ones the stages make in the mesh itself.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/io.h"
#include "island_meshes.h"
#include "test_meshes.h"

namespace holefill::testing {
namespace {

// The mesh's positions and faces' corners, in order, as text (compared bit for bit: %a).
std::string fingerprint(const Mesh& mesh) {
  std::string text;
  char number[64];
  for (const auto v : mesh.vertices()) {
    for (int axis = 0; axis < 3; ++axis) {
      std::snprintf(number, sizeof number, "%a ", mesh.point(v)[axis]);
      text += number;
    }
  }
  for (const auto f : mesh.faces()) {
    for (const auto v : mesh.fv_range(f)) text += std::to_string(v.idx()) + ' ';
  }
  return text;
}

// A grid with many square holes beside a sphere with two holes: more holes than most machines
// have cores, of different sizes.
Mesh many_holes() {
  Mesh mesh = grid_with_square_holes(40);
  append_mesh(mesh, sphere_with_two_holes(), Point(3, 0, 0));
  return mesh;
}

TEST(FillThreads, TheSameMeshAndFillsOnOneTwoAndMoreThreadsThanHoles) {
  std::vector<Mesh> meshes{many_holes()};
  meshes.push_back(load_mesh(std::filesystem::path(HOLEFILL_ASSETS_DIR) / "bunny.obj"));
  for (const Mesh& before : meshes) {
    const auto holes = find_holes(before);
    ASSERT_GT(holes.size(), 2u);
    Mesh one = before;
    FillOptions options;
    options.threads = 1;
    const auto fills_one = fill_holes(one, holes, options);
    for (const unsigned threads : {2u, 3u, 1000u}) {
      Mesh mesh = before;
      options.threads = threads;
      const auto fills = fill_holes(mesh, holes, options);
      EXPECT_EQ(fingerprint(mesh), fingerprint(one)) << threads << " threads";
      ASSERT_EQ(fills.size(), fills_one.size());
      for (std::size_t i = 0; i < fills.size(); ++i) {
        EXPECT_EQ(fills[i].hole_id, fills_one[i].hole_id);
        EXPECT_EQ(fills[i].failure, fills_one[i].failure);
        EXPECT_EQ(fills[i].stats.new_faces, fills_one[i].stats.new_faces);
        EXPECT_EQ(fills[i].stats.min_angle_deg, fills_one[i].stats.min_angle_deg);
      }
    }
  }
}

// Many holes of several sizes, a hole with an island inside it, and a tube cut in two; the ids
// of the tube's two facing loops (those nearest its middle).
Mesh holes_islands_and_a_gap(std::pair<int, int>& gap) {
  Mesh mesh = many_holes();
  const Point north(0.0, 0.0, 1.0);
  append_mesh(mesh,
              cut_around_islands(make_blob(3, [](const Point&) { return 1.0; }), {north, 0.7},
                                 {{north, 0.3}}),
              Point(0, 3, 0));
  append_mesh(mesh, tube_cut_in_two(24, 30, 14, 17), Point(3, 3, 0));
  const auto holes = find_holes(mesh);
  std::vector<int> by_middle;
  for (const auto& hole : holes) by_middle.push_back(hole.id);
  const Point middle(3, 3, 1.55);
  std::sort(by_middle.begin(), by_middle.end(), [&](int a, int b) {
    return (holes[a].centroid - middle).norm() < (holes[b].centroid - middle).norm();
  });
  gap = {by_middle[0], by_middle[1]};
  return mesh;
}

std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Every message and figure of a fill but its times.
std::string described(const HoleFill& fill) {
  char number[64];
  std::snprintf(number, sizeof number, "%a %a %a", fill.stats.min_angle_deg, fill.stats.area,
                fill.stats.max_dihedral_deg);
  std::string text = std::to_string(fill.hole_id) + " " + to_string(fill.stage()) + " " +
                     std::to_string(fill.stats.new_faces) + " " + number + " " +
                     to_string(fill.failure.kind) + " " + fill.failure.message + "|" +
                     fill.smoothing_note + "|" + fill.refinement_note + "|" + fill.attributes_note +
                     "|" + fill.islands_note + "|" + std::to_string(fill.self_intersections) + " " +
                     std::to_string(fill.refused_intersections) + " joined";
  for (const int id : fill.joined_holes) text += " " + std::to_string(id);
  for (const auto v : fill.patch.new_vertices) text += " v" + std::to_string(v.idx());
  for (const auto f : fill.patch.faces) text += " f" + std::to_string(f.idx());
  return text;
}

TEST(FillThreads, TheSameFilesAndFillsOnOneTwoThreeAndEightThreads) {
  std::pair<int, int> gap;
  const Mesh before = holes_islands_and_a_gap(gap);
  const auto holes = find_holes(before);
  ASSERT_GT(holes.size(), 40u);
  HoleSelection selection;
  selection.bridges = {gap};
  const auto dir = std::filesystem::temp_directory_path() /
                   ("holefill_fill_threads_" +
                    std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  std::filesystem::create_directories(dir);
  std::vector<std::string> files, fills_text;
  for (const unsigned threads : {1u, 2u, 3u, 8u}) {
    Mesh mesh = before;
    FillOptions options;
    options.threads = threads;
    const auto fills = fill_holes(mesh, holes, options, selection);
    std::string text;
    for (const auto& fill : fills) text += described(fill) + "\n";
    fills_text.push_back(text);
    const auto path = dir / ("filled_" + std::to_string(threads) + ".ply");
    save_mesh(mesh, path);
    files.push_back(file_bytes(path));
    if (threads == 1u) {
      // What was asked was made: the gap closed by one band, the island in its hole's patch.
      std::size_t joined = 0;
      for (const auto& fill : fills) joined += fill.joined_holes.size();
      EXPECT_GE(joined, 2u);
      EXPECT_LT(find_holes(mesh).size(), 4u);  // the tube's two ends, maybe
    }
  }
  std::filesystem::remove_all(dir);
  ASSERT_FALSE(files[0].empty());
  for (std::size_t t = 1; t < files.size(); ++t) {
    EXPECT_TRUE(files[t] == files[0]) << "file " << t;
    EXPECT_EQ(fills_text[t], fills_text[0]) << "fills " << t;
  }
}

// The independent truth: each group filled in the mesh itself, one after another in fill_holes'
// order (fill_joined_holes, no threads, no index), gives the mesh fill_holes gives on four
// threads, bit for bit.
TEST(FillThreads, PatchesMadeApartAreThoseMadeInTheMesh) {
  std::pair<int, int> gap;
  const Mesh before = holes_islands_and_a_gap(gap);
  const auto holes = find_holes(before);
  HoleSelection selection;
  selection.bridges = {gap};
  Mesh apart = before;
  FillOptions options;
  options.threads = 4;
  const auto fills = fill_holes(apart, holes, options, selection);
  ASSERT_GT(fills.size(), 40u);
  Mesh in_place = before;
  for (const auto& fill : fills) {
    std::vector<const Hole*> loops{&holes[fill.hole_id]};
    for (const int id : fill.joined_holes) loops.push_back(&holes[id]);
    const HoleFill one = fill_joined_holes(in_place, loops, options);
    HoleFill expected = fill;
    expected.islands_note.clear();  // fill_holes' word on the group, not the fill's
    EXPECT_EQ(described(one), described(expected));
  }
  EXPECT_EQ(fingerprint(in_place), fingerprint(apart));
}

// One large hole (its refined patch has several blocks of triangles to check and measure) is
// filled in the mesh itself, on every thread for its own stages: on 1, 2, 3 and more threads than
// blocks it gives the mesh and the fill that fill_joined_holes gives, bit for bit.
TEST(FillThreads, OneLargeHoleOnAnyThreadsIsFilledAsInPlace) {
  const Mesh before = without_faces(
      make_grid(200, [](double x, double y) { return 0.1 * std::sin(5.0 * x + 3.0 * y); }),
      [](const Point& c) { return (c - Point(0.5, 0.5, c[2])).norm() < 0.3; });
  const auto holes = find_holes(before);
  ASSERT_EQ(holes.size(), 2u);  // the grid's border, and the hole
  const auto largest = std::max_element(
      holes.begin(), holes.end(), [](const Hole& a, const Hole& b) { return a.size() < b.size(); });
  const Hole& hole = holes[largest == holes.begin() ? 1 : 0];
  Mesh in_place = before;
  const HoleFill expected = fill_joined_holes(in_place, {&hole}, FillOptions{});
  ASSERT_GT(expected.patch.faces.size(), 3u * 4096u);
  HoleSelection selection;
  selection.hole_ids = {hole.id};
  for (const unsigned threads : {1u, 2u, 3u, 1000u}) {
    Mesh mesh = before;
    FillOptions options;
    options.threads = threads;
    const auto fills = fill_holes(mesh, holes, options, selection);
    ASSERT_EQ(fills.size(), 1u);
    EXPECT_EQ(described(fills[0]), described(expected)) << threads << " threads";
    EXPECT_EQ(fingerprint(mesh), fingerprint(in_place)) << threads << " threads";
  }
}

}  // namespace
}  // namespace holefill::testing
