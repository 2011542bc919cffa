// The full search on several threads against the same search on one, and its vectorised pieces
// (the bound scan, the combination of keys) against plain loops: neither the number of threads
// nor the processor may change which triangulation is chosen.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <thread>

#include "bound_scan.h"
#include "dp_step.h"
#include "holefill/triangulate.h"
#include "test_meshes.h"
#include "weight_keys.h"

namespace holefill {
namespace {

// A planar regular polygon: many triangulations tie on every angle, so apex ties decide.
HolePolygon regular_polygon(int n) {
  HolePolygon polygon;
  for (int i = 0; i < n; ++i) {
    polygon.points.emplace_back(std::cos(2.0 * std::numbers::pi * i / n),
                                std::sin(2.0 * std::numbers::pi * i / n), 0.0);
  }
  polygon.outside_normals.assign(n, Point(0, 0, 1));
  return polygon;
}

std::vector<HolePolygon> test_holes() {
  std::mt19937 rng(97);
  std::vector<HolePolygon> holes;
  for (const int n : {3, 4, 5, 9, 17, 33, 64, 121}) {
    holes.push_back(testing::wavy_hole(n, 2 * n));
    holes.push_back(testing::wavy_hole(n, 2 * n + 1));
    std::bernoulli_distribution pick(0.2);
    for (int i = 0; i < n; ++i) {
      for (int k = i + 2; k < n; ++k) {
        if (pick(rng)) holes.back().forbidden_chords.emplace_back(i, k);
      }
    }
  }
  for (const int n : {12, 40, 96, 130}) holes.push_back(regular_polygon(n));
  // Every point on one line but the last: nearly everything is degenerate.
  HolePolygon flat = regular_polygon(30);
  for (int i = 0; i + 1 < 30; ++i) flat.points[i] = Point(i, 0.0, 0.0);
  holes.push_back(flat);
  return holes;
}

TEST(FullSearch, GivesTheSameTriangulationOnAnyNumberOfThreads) {
  for (const auto& polygon : test_holes()) {
    for (const auto weight : {WeightKind::MaxMin, WeightKind::Liepa, WeightKind::Area}) {
      for (const double fold_limit : {kDefaultFoldLimit, std::numbers::pi}) {
        TriangulateOptions serial{weight, fold_limit};
        serial.threads = 1;
        const auto expected = triangulate_polygon(polygon, serial);
        // More threads than this machine's cores, too: rows then wait on descheduled rows.
        for (const unsigned threads : {0u, 2u, 7u}) {
          TriangulateOptions parallel = serial;
          parallel.threads = threads;
          const auto result = triangulate_polygon(polygon, parallel);
          ASSERT_EQ(result.has_value(), expected.has_value());
          if (!result) continue;
          EXPECT_EQ(result->triangles, expected->triangles)
              << to_string(weight) << ", n = " << polygon.points.size() << ", fold " << fold_limit
              << ", " << threads << " threads";
          EXPECT_EQ(result->quality.area, expected->quality.area);
        }
      }
    }
  }
}

// The dynamic program as the paper states it, independent of the full search's strips, tables and
// threads: every cell row by row from the bottom, every apex in order, with the same one step
// (detail::try_apex) and plain n x n tables.
std::vector<std::array<int, 3>> row_by_row_reference(const HolePolygon& input, WeightKind kind) {
  const HolePolygon polygon = detail::canonical(input);  // unit normals, as the search makes them
  const int n = static_cast<int>(polygon.points.size());
  const auto cell = [n](int i, int k) { return static_cast<std::size_t>(i) * n + k; };
  std::vector<WeightValue> value(cell(n, 0));  // polygon edges (k = i + 1) keep {0, 0}
  std::vector<int> apex(cell(n, 0), -1);
  std::vector<Point> normal(cell(n, 0), Point(0, 0, 0));
  std::vector<bool> forbidden(cell(n, 0), false);
  for (const auto& [a, b] : polygon.forbidden_chords) {
    forbidden[cell(std::min(a, b), std::max(a, b))] = true;
  }
  const auto normal_across = [&](int a, int b) -> const Point& {
    return b == a + 1 ? polygon.outside_normals[a] : normal[cell(a, b)];
  };
  TriangulateOptions options{kind};
  detail::with_weight(options, [&](const auto& weight) {
    for (int i = n - 3; i >= 0; --i) {
      for (int k = i + 2; k < n; ++k) {
        detail::CellBest best;
        if (!forbidden[cell(i, k)] || (i == 0 && k == n - 1)) {
          for (int m = i + 1; m < k; ++m) {
            const WeightValue& left = value[cell(i, m)];
            const WeightValue& right = value[cell(m, k)];
            if (left.key == detail::weight_key::kInfeasible ||
                right.key == detail::weight_key::kInfeasible) {
              continue;
            }
            detail::try_apex<false>(weight, polygon, i, m, k, left,
                                    detail::SideValue{right.key, right.area, &right.area},
                                    normal_across, best);
          }
        }
        apex[cell(i, k)] = best.apex;
        value[cell(i, k)] =
            best.apex >= 0 ? best.value : WeightValue{detail::weight_key::kInfeasible, INFINITY};
        if (best.apex >= 0) {
          normal[cell(i, k)] =
              detail::unit_normal(polygon.points[i], polygon.points[best.apex], polygon.points[k]);
        }
      }
    }
    return 0;
  });
  if (apex[cell(0, n - 1)] < 0) return {};
  return detail::trace_triangles(n, [&](int i, int k) { return apex[cell(i, k)]; });
}

// Strips of rows meet at every eighth or sixteenth row and run on different threads: holes whose
// rows end anywhere in a strip, with forbidden chords, give the reference's triangulation.
TEST(FullSearch, MatchesTheRowByRowDynamicProgramAcrossStrips) {
  std::mt19937 rng(5);
  for (const int n : {6, 10, 17, 18, 19, 25, 34, 47, 66, 131, 200}) {
    HolePolygon polygon = testing::wavy_hole(n, 7 * n);
    std::bernoulli_distribution pick(0.05);
    for (int i = 0; i < n; ++i) {
      for (int k = i + 2; k < n; ++k) {
        if (pick(rng)) polygon.forbidden_chords.emplace_back(i, k);
      }
    }
    for (const auto weight : {WeightKind::MaxMin, WeightKind::Liepa, WeightKind::Area}) {
      const auto expected = row_by_row_reference(polygon, weight);
      for (const unsigned threads : {1u, 2u, 3u}) {
        for (const bool prune : {true, false}) {
          TriangulateOptions options{weight};
          options.threads = threads;
          options.prune = prune;
          options.restricted.above_edges = 0;
          const auto result = triangulate_polygon(polygon, options);
          ASSERT_EQ(result.has_value(), !expected.empty()) << "n = " << n;
          if (result) {
            EXPECT_EQ(result->triangles, expected) << to_string(weight) << ", n = " << n << ", "
                                                   << threads << " threads, prune " << prune;
          }
        }
      }
    }
  }
}

TEST(FullSearch, ThePlainLoopOnThreadsMatchesThePrunedSearchOnOne) {
  for (int trial = 0; trial < 4; ++trial) {
    const HolePolygon polygon = testing::wavy_hole(40 + 30 * trial, trial);
    for (const auto weight : {WeightKind::MaxMin, WeightKind::Liepa}) {
      TriangulateOptions pruned{weight}, plain{weight};
      pruned.threads = 1;
      plain.prune = false;
      plain.threads = 3;
      EXPECT_EQ(triangulate_polygon(polygon, plain)->triangles,
                triangulate_polygon(polygon, pruned)->triangles)
          << to_string(weight) << ", n = " << polygon.points.size();
    }
  }
}

// A cancel from another thread stops the search between rows, whatever the number of threads
// (a thread waiting on a row that is never taken would hang here).
TEST(FullSearch, StopsAndReturnsNothingWhenCancelled) {
  const HolePolygon polygon = testing::wavy_hole(2000);
  for (const unsigned threads : {1u, 3u}) {
    Progress progress;
    TriangulateOptions options;
    options.restricted.above_edges = 0;
    options.threads = threads;
    options.progress = &progress;
    std::jthread canceller([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      progress.cancel();
    });
    EXPECT_FALSE(triangulate_polygon(polygon, options)) << threads << " threads";
    EXPECT_TRUE(progress.cancelled());
  }
}

TEST(RestrictedSearch, ReturnsNothingWhenCancelled) {
  Progress progress;
  progress.cancel();
  TriangulateOptions options;
  options.progress = &progress;
  EXPECT_FALSE(triangulate_polygon_restricted(testing::wavy_hole(1000), options));
  EXPECT_FALSE(triangulate_polygon(testing::wavy_hole(1000), options));
}

// The larger of a's and b's value in each 16-bit lane, lane by lane.
std::uint64_t lane_max_by_hand(std::uint64_t a, std::uint64_t b) {
  std::uint64_t lanes = 0;
  for (int shift = 0; shift < 64; shift += 16) {
    lanes |= std::max((a >> shift) & 0xFFFF, (b >> shift) & 0xFFFF) << shift;
  }
  return lanes;
}

// Candidates for the bound scan, held in vectors (detail::ApexRun points into them).
struct Candidates {
  std::vector<std::uint64_t> left_key, right_key;
  std::vector<double> left_area;
  std::vector<float> right_area;
  std::vector<double> x, y, z;

  detail::ApexRun run() const {
    return {left_key.data(), right_key.data(), left_area.data(), right_area.data(),
            x.data(),        y.data(),         z.data(),         static_cast<int>(x.size())};
  }
};

// Whether candidate j is ruled out, by BoundScan's rule written out with OpenMesh's vectors.
bool ruled_out_by_hand(const Candidates& c, const detail::ApexBase& base, detail::BestSoFar best,
                       std::size_t j) {
  const std::uint64_t bound = lane_max_by_hand(c.left_key[j], c.right_key[j]);
  if (bound != best.key) return bound > best.key;
  const double sides = c.left_area[j] + static_cast<double>(c.right_area[j]);
  const Point to_m =
      Point(c.x[j], c.y[j], c.z[j]) - Point(base.origin[0], base.origin[1], base.origin[2]);
  const Point to_k(base.to_k[0], base.to_k[1], base.to_k[2]);
  return sides > best.area ||
         OpenMesh::cross(to_m, to_k).sqrnorm() > detail::squared_twice_room(best.area, sides);
}

TEST(BoundScan, FindsTheFirstApexNotRuledOutLikeAPlainLoop) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const detail::BoundScan fastest = detail::fastest_bound_scan();
  // Keys from a few values (ties with the bound; lanes that a plain maximum of the keys would
  // not combine) and from the whole range (the top bit set: unsigned order, not signed), at every
  // length around the vector width; areas and points such that ties go either way.
  const std::vector<std::uint64_t> few{
      0, 5, 6, 7, 0x0005'0000, 0x0005'0006, 0x8000000000000000ull, ~0ull};
  int ties_ruled_out = 0, ties_kept = 0;
  for (int trial = 0; trial < 8000; ++trial) {
    const int count = trial % 40;
    const bool from_few = trial % 2 == 0;
    auto draw = [&] { return from_few ? few[rng() % few.size()] : rng(); };
    Candidates c;
    for (int j = 0; j < count; ++j) {
      c.left_key.push_back(draw());
      c.right_key.push_back(draw());
      c.left_area.push_back(1.0 + unit(rng));
      c.right_area.push_back(static_cast<float>(1.0 + unit(rng)));
      c.x.push_back(unit(rng));
      c.y.push_back(unit(rng));
      c.z.push_back(unit(rng));
    }
    const detail::ApexBase base{{unit(rng), unit(rng), unit(rng)},
                                {unit(rng), unit(rng), unit(rng)}};
    const detail::BestSoFar best{draw(), 3.0 + 1.5 * unit(rng)};
    int expected = count;
    for (int j = 0; j < count; ++j) {
      const bool tie = lane_max_by_hand(c.left_key[j], c.right_key[j]) == best.key;
      const bool out = ruled_out_by_hand(c, base, best, static_cast<std::size_t>(j));
      if (tie) ++(out ? ties_ruled_out : ties_kept);
      if (!out) {
        expected = j;
        break;
      }
    }
    EXPECT_EQ(detail::first_within_bound_portable(c.run(), base, best), expected);
    EXPECT_EQ(fastest(c.run(), base, best), expected);
  }
  EXPECT_GT(ties_ruled_out, 100);  // the area tests were exercised both ways
  EXPECT_GT(ties_kept, 100);
}

// combine() packs three lane maxima into a few SIMD instructions: against the lanes one by one.
TEST(WeightKey, CombineAddsDegenerateCountsAndTakesTheLargerOfEachAngleLane) {
  std::mt19937_64 rng(13);
  const std::vector<std::uint64_t> lane_values{0, 1, 0x7FFF, 0x8000, 0xFFFE, 0xFFFF};
  auto draw_key = [&] {
    // Degenerate counts stay below 0x8000 (fewer points than kMaxPolygonSize, two sides).
    std::uint64_t key = (rng() % 0x8000) << detail::weight_key::kDegenerateShift;
    for (const int shift :
         {detail::weight_key::kLaneA, detail::weight_key::kLaneB, detail::weight_key::kLaneC}) {
      key |= (rng() % 2 ? lane_values[rng() % lane_values.size()] : rng() & 0xFFFF) << shift;
    }
    return key;
  };
  for (int trial = 0; trial < 20000; ++trial) {
    const std::uint64_t a = draw_key(), b = draw_key();
    std::uint64_t expected = ((a >> 48) + (b >> 48)) << 48;
    for (const int shift : {0, 16, 32}) {
      expected |= std::max((a >> shift) & 0xFFFF, (b >> shift) & 0xFFFF) << shift;
    }
    ASSERT_EQ(detail::weight_key::combine(a, b), expected) << std::hex << a << " " << b;
  }
}

// The apex loop's bound: lane by lane, never above what a weight's combination gives (pruning by
// it is exact) and never below the larger key (it prunes at least as much).
TEST(WeightKey, LaneMaxBoundsEveryWeightsCombinationFromBelow) {
  std::mt19937_64 rng(17);
  const std::vector<std::uint64_t> lane_values{0, 1, 0x7FFF, 0x8000, 0xFFFE, 0xFFFF};
  auto draw_lane = [&] {
    return rng() % 2 ? lane_values[rng() % lane_values.size()] : rng() & 0xFFFF;
  };
  const detail::MaxMinWeight max_min;
  const detail::LiepaWeight liepa;
  for (int trial = 0; trial < 20000; ++trial) {
    // Degenerate counts below 0x8000, as in combine's test; Liepa sets lane A alone.
    const std::uint64_t count_a = (rng() % 0x8000) << 48, count_b = (rng() % 0x8000) << 48;
    const std::uint64_t a = count_a | draw_lane() << 32 | draw_lane() << 16 | draw_lane();
    const std::uint64_t b = count_b | draw_lane() << 32 | draw_lane() << 16 | draw_lane();
    const std::uint64_t bound = detail::weight_key::lane_max(a, b);
    ASSERT_EQ(bound, lane_max_by_hand(a, b)) << std::hex << a << " " << b;
    EXPECT_GE(bound, std::max(a, b));
    EXPECT_LE(bound, max_min.combine(a, b));
    const std::uint64_t liepa_a = count_a | (a & 0xFFFF'0000'0000),
                        liepa_b = count_b | (b & 0xFFFF'0000'0000);
    EXPECT_LE(detail::weight_key::lane_max(liepa_a, liepa_b), liepa.combine(liepa_a, liepa_b));
    EXPECT_LE(detail::weight_key::lane_max(count_a, count_b),
              detail::AreaWeight::combine(count_a, count_b));
  }
  EXPECT_EQ(detail::weight_key::lane_max(detail::weight_key::kInfeasible, 0),
            detail::weight_key::kInfeasible);
}

}  // namespace
}  // namespace holefill
