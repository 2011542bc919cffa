#include "hole_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "valence_bins.h"

namespace holefill::viewer {
namespace {

Session bunny() {
  Session session;
  EXPECT_TRUE(session.open(std::filesystem::path(HOLEFILL_TEST_ASSETS) / "bunny.obj"));
  return session;
}

std::vector<int> ids(const std::vector<HoleRow>& rows) {
  std::vector<int> result;
  for (const auto& row : rows) result.push_back(row.id);
  return result;
}

TEST(HoleTable, PolygonAreaOfAUnitSquareInAnyPlane) {
  EXPECT_DOUBLE_EQ(polygon_area({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}), 1.0);
  EXPECT_DOUBLE_EQ(polygon_area({{0, 0, 0}, {0, 2, 0}, {0, 2, 3}, {0, 0, 3}}), 6.0);
}

TEST(HoleTable, SortsByEveryColumnBothWays) {
  Session session = bunny();  // holes of 99, 37 and 28 edges
  session.select(1);
  ASSERT_TRUE(session.fill_selected());
  const auto rows = hole_rows(session);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_GT(rows[0].area, rows[1].area);
  EXPECT_GT(rows[1].area, rows[2].area);
  HoleView view;
  EXPECT_EQ(ids(arrange(rows, view)), (std::vector<int>{0, 1, 2}));
  view.column = HoleColumn::Edges;
  EXPECT_EQ(ids(arrange(rows, view)), (std::vector<int>{2, 1, 0}));
  view.descending = true;
  EXPECT_EQ(ids(arrange(rows, view)), (std::vector<int>{0, 1, 2}));
  view.column = HoleColumn::Perimeter;
  EXPECT_EQ(ids(arrange(rows, view)), (std::vector<int>{0, 1, 2}));
  view.column = HoleColumn::Area;
  view.descending = false;
  EXPECT_EQ(ids(arrange(rows, view)), (std::vector<int>{2, 1, 0}));
  view.column = HoleColumn::Status;  // open before filled, ties by id
  EXPECT_EQ(ids(arrange(rows, view)), (std::vector<int>{0, 2, 1}));
}

TEST(HoleTable, FiltersByStatus) {
  Session session = bunny();
  session.select(2);
  ASSERT_TRUE(session.fill_selected());
  session.select(0);
  ASSERT_TRUE(session.step(Stage::Triangulated));
  const auto rows = hole_rows(session);
  EXPECT_EQ(rows[0].status, HoleStatus::Partial);
  EXPECT_EQ(rows[0].stage, "triangulated");
  HoleView view;
  view.only_filled = true;
  EXPECT_EQ(ids(arrange(rows, view)), (std::vector<int>{2}));
  view.only_open = true;  // either
  EXPECT_EQ(ids(arrange(rows, view)), (std::vector<int>{1, 2}));
  view = {};
  view.only_failed = true;
  EXPECT_TRUE(arrange(rows, view).empty());
}

TEST(HoleTable, AFailedHoleNamesThePanelsControlThatHelps) {
  Session refused;  // a border every cap of which cuts the surface
  ASSERT_TRUE(refused.open(std::filesystem::path(HOLEFILL_TEST_ASSETS) / "ragged_disk.obj"));
  refused.select(0);
  EXPECT_FALSE(refused.fill_selected());
  EXPECT_EQ(hole_rows(refused)[0].remedy, "\"keep cutting patches\" keeps it");
  EXPECT_EQ(hole_rows(refused)[1].remedy, "");
  // 20 lone triangles around one vertex: one loop through it 20 times, refused (the core's
  // kMaxVertexPasses is 16); the triangles are small pieces, so the button shows.
  const auto file = std::filesystem::temp_directory_path() / "holefill_hole_table_fan.obj";
  {
    std::ofstream out(file);
    out << "v 0 0 0\n";
    for (int i = 0; i < 20; ++i) {
      const double a = 2.0 * std::numbers::pi * i / 20, b = 2.0 * std::numbers::pi * (i + 0.5) / 20;
      out << "v " << std::cos(a) << " " << std::sin(a) << " " << 0.01 * (i % 7) << "\nv "
          << std::cos(b) << " " << std::sin(b) << " " << 0.01 * (i % 5) << "\n";
    }
    for (int i = 0; i < 20; ++i) out << "f 1 " << 2 + 2 * i << " " << 3 + 2 * i << "\n";
  }
  Session fan;
  ASSERT_TRUE(fan.open(file)) << fan.notice().text;
  std::filesystem::remove(file);
  ASSERT_EQ(fan.holes().size(), 1u);
  fan.select(0);
  EXPECT_FALSE(fan.fill_selected());
  EXPECT_EQ(fan.fill(0).failure.kind, FailureKind::VertexPassedTooOften) << fan.fill(0).failure;
  EXPECT_EQ(hole_rows(fan)[0].remedy, "\"Remove small pieces\" removes the pieces that meet there");
  EXPECT_GT(fan.pieces().lone_triangles, 0u);
}

TEST(ValenceBins, OutliersFallInTheEndBinsAndEveryVertexCounts) {
  const auto bins = valence_bins({{0, 1}, {2, 3}, {3, 4}, {6, 50}, {9, 2}, {10, 5}, {17, 1}});
  EXPECT_STREQ(bins[0].label, "<=2");
  EXPECT_EQ(bins[0].count, 4u);
  EXPECT_EQ(bins[1].count, 4u);   // valence 3
  EXPECT_EQ(bins[4].count, 50u);  // valence 6
  EXPECT_STREQ(bins[4].label, "6");
  EXPECT_EQ(bins[7].count, 2u);  // valence 9
  EXPECT_STREQ(bins[8].label, ">=10");
  EXPECT_EQ(bins[8].count, 6u);
  std::size_t total = 0;
  for (const auto& bin : bins) total += bin.count;
  EXPECT_EQ(total, 66u);
}

// The labels drawn under a chart lie within it and at least `gap` apart; a chart wide enough
// shows them all, a half-width one (the comparison's, 175 px at 7 px a character) every other,
// a narrower one every fourth.
TEST(ValenceBins, LabelsStayInsideTheChartAndNeverTouch) {
  const std::array<float, kValenceBins> widths{21, 7, 7, 7, 7, 7, 7, 7, 28};  // "<=2" .. ">=10"
  const float gap = 4.0f;
  for (const float width : {360.0f, 175.0f, 120.0f}) {
    const auto x = label_positions(widths, width, gap);
    float previous_end = -gap;
    std::size_t shown = 0;
    for (std::size_t i = 0; i < kValenceBins; ++i) {
      if (!x[i]) continue;
      ++shown;
      EXPECT_GE(*x[i], 0.0f) << width;
      EXPECT_LE(*x[i] + widths[i], width) << width;
      EXPECT_GE(*x[i], previous_end + gap) << "label " << i << " in a chart " << width << " wide";
      previous_end = *x[i] + widths[i];
    }
    EXPECT_TRUE(x[0] && x[kValenceBins - 1]) << width;  // the ends always say where they are
    EXPECT_EQ(shown, width > 300.0f ? kValenceBins : width > 150.0f ? 5u : 3u) << width;
  }
}

TEST(ValenceBins, LogHeightsKeepSmallBinsVisible) {
  EXPECT_DOUBLE_EQ(bar_height(50, 100, false), 0.5);
  EXPECT_DOUBLE_EQ(bar_height(100, 100, true), 1.0);
  EXPECT_GT(bar_height(10, 100000, true), 0.2);
  EXPECT_LT(bar_height(10, 100000, false), 1e-3);
  EXPECT_DOUBLE_EQ(bar_height(0, 0, true), 0.0);
}

}  // namespace
}  // namespace holefill::viewer
