// The coarse proxy drawn while the camera moves over a big mesh: far fewer triangles, on the
// surface it stands for, facing the same way, with the stages and colours of what it replaces.
// The truth here is the unit sphere the test mesh approximates.
#include "coarse_proxy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "test_meshes.h"

namespace holefill::viewer {
namespace {

// A unit icosphere of 81,920 triangles, as the renderer would upload it.
SurfaceArrays fine_sphere() { return surface_arrays(holefill::testing::make_icosphere(6), {}); }

double proxy_area(const SurfaceArrays& arrays) {
  double area = 0.0;
  for (std::size_t t = 0; t < arrays.triangles.size(); t += 3) {
    const glm::vec3& a = arrays.positions[arrays.triangles[t]];
    const glm::vec3& b = arrays.positions[arrays.triangles[t + 1]];
    const glm::vec3& c = arrays.positions[arrays.triangles[t + 2]];
    area += 0.5 * glm::length(glm::cross(b - a, c - a));
  }
  return area;
}

TEST(CoarseProxy, FewerTrianglesOnTheSameSurfaceFacingOutward) {
  const SurfaceArrays full = fine_sphere();
  ASSERT_EQ(full.triangles.size() / 3, 81920u);
  const SurfaceArrays proxy = coarse_proxy(full, 2000);
  const std::size_t triangles = proxy.triangles.size() / 3;
  EXPECT_GE(triangles, 500u);
  EXPECT_LE(triangles, 4000u);
  ASSERT_EQ(proxy.face_stages.size(), triangles);
  ASSERT_EQ(proxy.normals.size(), proxy.positions.size());
  // The cells are about sqrt(4 pi / 1000) = 0.11 across: the proxy stays that close to the sphere.
  for (const auto& p : proxy.positions) EXPECT_NEAR(glm::length(p), 1.0f, 0.06f);
  for (std::size_t v = 0; v < proxy.positions.size(); ++v) {
    EXPECT_GT(glm::dot(proxy.normals[v], glm::normalize(proxy.positions[v])), 0.5f);
  }
  // No triangle is folded over: each faces out of the sphere.
  for (std::size_t t = 0; t < proxy.triangles.size(); t += 3) {
    const glm::vec3& a = proxy.positions[proxy.triangles[t]];
    const glm::vec3& b = proxy.positions[proxy.triangles[t + 1]];
    const glm::vec3& c = proxy.positions[proxy.triangles[t + 2]];
    EXPECT_GT(glm::dot(glm::cross(b - a, c - a), a + b + c), 0.0f) << "triangle " << t / 3;
  }
  // Its triangles cover the sphere about once (a chordal polyhedron is a little smaller).
  EXPECT_NEAR(proxy_area(proxy), 4.0 * std::numbers::pi, 0.1 * 4.0 * std::numbers::pi);
  EXPECT_EQ(proxy.lo, full.lo);
  EXPECT_EQ(proxy.hi, full.hi);
}

TEST(CoarseProxy, KeepsTheStagesAndColoursOfWhatItReplaces) {
  SurfaceArrays full = fine_sphere();
  full.face_stages.assign(full.face_stages.size(), static_cast<std::uint8_t>(Stage::Smoothed));
  full.colors.assign(full.positions.size(), glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
  const SurfaceArrays proxy = coarse_proxy(full, 2000);
  ASSERT_FALSE(proxy.triangles.empty());
  for (const auto stage : proxy.face_stages) {
    EXPECT_EQ(stage, static_cast<std::uint8_t>(Stage::Smoothed));
  }
  ASSERT_EQ(proxy.colors.size(), proxy.positions.size());
  for (const auto& color : proxy.colors) EXPECT_EQ(color, glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
}

TEST(CoarseProxy, NeverMoreTrianglesThanTheMesh) {
  const SurfaceArrays full = surface_arrays(holefill::testing::make_icosphere(2), {});
  const SurfaceArrays proxy = coarse_proxy(full, 1'000'000);
  EXPECT_LE(proxy.triangles.size(), full.triangles.size());
  EXPECT_GT(proxy.triangles.size(), full.triangles.size() / 2);
}

}  // namespace
}  // namespace holefill::viewer
