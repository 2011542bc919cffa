// fill_holes on any number of threads (FillOptions::threads) gives the same mesh and the same
// fills as on one: the holes are planned in parallel but added in order, and each dynamic
// program's result does not depend on its threads.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/io.h"
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

}  // namespace
}  // namespace holefill::testing
