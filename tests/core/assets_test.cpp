// Every bundled asset, filled with every weight: no hole left, an oriented manifold of the
// expected genus, the original part untouched.
#include <gtest/gtest.h>

#include <filesystem>
#include <numbers>

#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/io.h"
#include "test_meshes.h"

namespace holefill {
namespace {

long elements_euler_characteristic(const Mesh& mesh) {
  return static_cast<long>(mesh.n_vertices()) - static_cast<long>(mesh.n_edges()) +
         static_cast<long>(mesh.n_faces());
}

struct AssetCase {
  std::string file;
  long euler_when_closed;  // 2 - 2 * genus
};

class FillAsset : public ::testing::TestWithParam<std::tuple<AssetCase, WeightKind>> {};

TEST_P(FillAsset, ClosesEveryHoleAndKeepsTheOriginal) {
  const auto& [asset, weight] = GetParam();
  const Mesh before = load_mesh(std::filesystem::path(HOLEFILL_ASSETS_DIR) / asset.file);
  const auto holes = find_holes(before);
  ASSERT_FALSE(holes.empty());
  Mesh mesh = before;
  FillOptions options;
  options.triangulate.weight = weight;
  for (const auto& fill : fill_holes(mesh, holes, options)) {
    EXPECT_FALSE(fill.failed()) << "hole " << fill.hole_id << ": " << fill.failure;
    EXPECT_GT(fill.stats.min_angle_deg, 0.0);
  }
  EXPECT_TRUE(find_holes(mesh).empty());
  EXPECT_TRUE(testing::is_oriented_manifold(mesh));
  EXPECT_EQ(elements_euler_characteristic(mesh), asset.euler_when_closed);
  EXPECT_TRUE(testing::original_part_unchanged(before, mesh));
}

INSTANTIATE_TEST_SUITE_P(
    Assets, FillAsset,
    ::testing::Combine(::testing::Values(AssetCase{"sphere.obj", 2}, AssetCase{"heart.obj", 2},
                                         AssetCase{"bunny.obj", 2}, AssetCase{"torus.obj", 0}),
                       ::testing::Values(WeightKind::MaxMin, WeightKind::Liepa, WeightKind::Area)),
    [](const auto& info) {
      std::string name = std::get<0>(info.param).file;
      name = name.substr(0, name.find('.'));
      return name + "_" + to_string(std::get<1>(info.param));
    });

// On the sphere's ragged 406-edge hole the paper's order buys its smallest angle with a patch
// folded over itself; the default fold limit keeps maxmin's patch unfolded.
TEST(MaxMinFoldLimit, KeepsTheSpherePatchUnfolded) {
  const Mesh before = load_mesh(std::filesystem::path(HOLEFILL_ASSETS_DIR) / "sphere.obj");
  const auto holes = find_holes(before);
  ASSERT_EQ(holes.size(), 1u);
  auto max_dihedral_deg = [&](double fold_limit) {
    Mesh mesh = before;
    FillOptions options;
    options.triangulate.fold_limit = fold_limit;
    options.last_stage = Stage::Triangulated;
    return fill_hole(mesh, holes[0], options).stats.max_dihedral_deg;
  };
  EXPECT_GT(max_dihedral_deg(std::numbers::pi), 90.0);
  EXPECT_LT(max_dihedral_deg(kDefaultFoldLimit), 90.0);
}

}  // namespace
}  // namespace holefill
