// The viewer's sharp features (feature_view.h, issue 35): what it draws near the selected hole
// lies on the true crease, follows the threshold, and Compare shows the fill without and with.
#include "feature_view.h"

#include <gtest/gtest.h>

#include "cad_parts.h"
#include "session.h"
#include "test_meshes.h"

namespace holefill::viewer {
namespace {

// The cube [0, 1]^3 (ten squares along each edge) with a hole around the middle of its edge
// along x at y = z = 0: a straight 90-degree crease runs through the hole.
Mesh cube_with_a_hole_across_an_edge() {
  const auto lines = testing::grid_lines({{0.1, 10}});
  const Mesh cube = testing::surface_of({lines, lines, lines, [](int, int, int) { return true; }});
  return testing::without_faces(
      cube, [](const Point& centroid) { return (centroid - Point(0.5, 0.0, 0.0)).norm() < 0.22; });
}

TEST(FeatureView, TheSelectedHolesCreaseIsDrawnOnTheTrueEdgeAndFollowsTheThreshold) {
  Session session;
  session.load(cube_with_a_hole_across_an_edge(), "cube");
  ASSERT_EQ(session.holes().size(), 1u);
  EXPECT_TRUE(session.selected_features().lines.empty());  // nothing selected
  session.select(0);
  const HoleFeatures& features = session.selected_features();
  ASSERT_EQ(features.lines.size(), 2u) << features.note;
  ASSERT_TRUE(features.continued()) << features.note;
  EXPECT_EQ(feature_summary(features),
            "2 sharp feature lines enter the hole: continued as a crease");
  const auto traced = feature_segments(features, false);
  const auto continued = feature_segments(features, true);
  ASSERT_FALSE(traced.empty());
  ASSERT_FALSE(continued.empty());
  float lowest = 1.0f, highest = 0.0f;  // of the continuation along the edge
  for (const auto* segments : {&traced, &continued}) {
    for (const auto& segment : *segments) {
      for (const glm::vec3& p : {segment.a, segment.b}) {
        EXPECT_NEAR(p.y, 0.0f, 1e-5f);
        EXPECT_NEAR(p.z, 0.0f, 1e-5f);
        if (segments == &continued) {
          lowest = std::min(lowest, p.x);
          highest = std::max(highest, p.x);
        }
      }
    }
  }
  // From one side of the hole to the other (it spans about 0.3 to 0.7 along the edge).
  EXPECT_LT(lowest, 0.35f);
  EXPECT_GT(highest, 0.65f);

  const std::uint64_t version = session.features_version();
  FillOptions off = session.options();
  off.features.angle_degrees = 0.0;
  session.set_options(off);
  EXPECT_TRUE(session.selected_features().lines.empty());
  EXPECT_NE(session.features_version(), version);
  // A threshold above the crease's 90 degrees sees no line either.
  FillOptions steep = session.options();
  steep.features.angle_degrees = 120.0;
  session.set_options(steep);
  EXPECT_TRUE(session.selected_features().lines.empty());
}

TEST(FeatureView, CompareShowsThePapersFillBesideTheCreaseContinued) {
  Session session;
  session.load(cube_with_a_hole_across_an_edge(), "cube");
  session.select(0);
  session.set_compare_mode(CompareMode::Features);
  session.set_compare(true);
  const Comparison* comparison = session.comparison();
  ASSERT_NE(comparison, nullptr);
  EXPECT_EQ(comparison->left.label, "paper");
  EXPECT_EQ(comparison->right.label, "creases");
  ASSERT_FALSE(comparison->left.fill.failed()) << comparison->left.fill.failure;
  ASSERT_FALSE(comparison->right.fill.failed()) << comparison->right.fill.failure;
  EXPECT_TRUE(comparison->left.fill.creases.empty());
  ASSERT_FALSE(comparison->right.fill.creases.empty());
  // The right side's new vertices lie on the cube's two faces there (y = 0 or z = 0).
  for (const auto v : comparison->right.fill.patch.new_vertices) {
    const Point& p = comparison->right.mesh.point(v);
    EXPECT_LT(std::min(std::abs(p[1]), std::abs(p[2])), 1e-6) << p;
  }
}

}  // namespace
}  // namespace holefill::viewer
