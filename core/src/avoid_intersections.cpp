#include "avoid_intersections.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

#include "hole_triangulation.h"
#include "patch_intersections.h"

namespace holefill::detail {
namespace {

// Solves of the dynamic program after the first: with the chosen weight, then with each other.
constexpr int kRoundsWithChosenWeight = 12;
constexpr int kRoundsWithOtherWeight = 6;
// Up to this many edges a round whose restricted search finds nothing runs the full search, as
// the plan does (up to about 1.5 s a round); above it the rounds keep to the restricted search,
// and only its chords are tested against the mesh: a 2,400-edge loop paid 15 s a round, and 28 s
// to test its 2.9M chords.
constexpr std::size_t kFullSearchInRoundsUpTo = 1500;

std::vector<WeightKind> weights_in_order(WeightKind chosen) {
  std::vector<WeightKind> order{chosen};
  for (const auto other : {WeightKind::MaxMin, WeightKind::Liepa, WeightKind::Area}) {
    if (other != chosen) order.push_back(other);
  }
  return order;
}

class Checker {
 public:
  Checker(const Mesh& mesh, const HolePolygon& polygon, const MeshFaceIndex* around, bool exact_too,
          const Progress* progress)
      : mesh_(mesh),
        polygon_(polygon),
        around_(around),
        exact_too_(exact_too),
        progress_(progress) {}

  std::vector<IntersectingPair> pairs(const PolygonTriangulation& triangulation) {
    std::vector<std::array<Point, 3>> corners;
    for (const auto& t : triangulation.triangles) {
      corners.push_back({polygon_.points[t[0]], polygon_.points[t[1]], polygon_.points[t[2]]});
    }
    return triangle_intersections(mesh_, corners, nullptr, grid(), exact_too_, progress_);
  }

 private:
  // The mesh's faces: the caller's index, or one of the faces near the polygon made on the first
  // round that needs it.
  const MeshFaceIndex* grid() {
    if (around_ || checks_++ == 0) return around_;
    Box reach;
    for (const auto& p : polygon_.points) reach.add(p);
    own_.emplace(mesh_, std::vector<Box>{reach});
    around_ = &*own_;
    return around_;
  }

  const Mesh& mesh_;
  const HolePolygon& polygon_;
  const MeshFaceIndex* around_;
  bool exact_too_;
  const Progress* progress_;
  std::optional<MeshFaceIndex> own_;
  int checks_ = 0;
};

// Forbids the triangles of `triangulation` that take part in `pairs`: a triangle crossing the
// mesh crosses it in any triangulation; of two patch triangles crossing each other, both go.
void forbid(const PolygonTriangulation& triangulation, const std::vector<IntersectingPair>& pairs,
            std::set<std::array<int, 3>>& forbidden) {
  for (const auto& pair : pairs) {
    forbidden.insert(triangulation.triangles[pair.triangle]);
    if (pair.other_triangle >= 0) forbidden.insert(triangulation.triangles[pair.other_triangle]);
  }
}

}  // namespace

PlannedTriangulation avoid_intersections(const Mesh& mesh, const Hole& hole,
                                         PlannedTriangulation plan,
                                         const TriangulateOptions& options,
                                         const MeshFaceIndex* around, IntersectionAvoidance& report,
                                         std::size_t& pairs, bool exact_too) {
  report = {};
  pairs = 0;
  if (!plan.triangulation) return plan;
  HolePolygon polygon = hole_polygon(mesh, hole);
  Checker checker(mesh, polygon, around, exact_too, options.progress);
  std::vector<IntersectingPair> found = checker.pairs(*plan.triangulation);
  pairs = report.first_pairs = found.size();
  if (found.empty()) return plan;

  // Chords through the mesh are forbidden at once: every triangle with such a side intersects.
  // A hole the rounds below leave to the restricted search alone needs only its chords tested
  // (a 2,400-edge loop has 2.9M chords, the restricted search about 150K).
  const bool restricted_alone = options.restricted.above_edges > 0 &&
                                polygon.points.size() > options.restricted.above_edges &&
                                polygon.points.size() > kFullSearchInRoundsUpTo;
  std::vector<std::pair<int, int>> restricted;
  if (restricted_alone) {
    restricted = restricted_chords(polygon, options.restricted);
    std::sort(restricted.begin(), restricted.end());
  }
  for (const auto& chord :
       chords_through_mesh(mesh, polygon.points, around, restricted_alone ? &restricted : nullptr,
                           options.progress)) {
    polygon.forbidden_chords.push_back(chord);
  }
  std::set<std::array<int, 3>> forbidden;
  PolygonTriangulation current = *plan.triangulation;
  for (const WeightKind weight : weights_in_order(options.weight)) {
    TriangulateOptions with = options;
    with.weight = weight;
    // The plan may have come from the full search, where the restricted one folded or found
    // nothing; the rounds fall back to it only where the restricted search finds nothing, and
    // only up to kFullSearchInRoundsUpTo edges.
    with.restricted.full_search_above_dihedral = INFINITY;
    with.restricted.full_search_fallback = !restricted_alone;
    const int rounds = weight == options.weight ? kRoundsWithChosenWeight : kRoundsWithOtherWeight;
    for (int round = 0; round < rounds; ++round) {
      forbid(current, found, forbidden);
      polygon.forbidden_triangles.assign(forbidden.begin(), forbidden.end());
      auto next = triangulate_polygon(polygon, with);
      ++report.rounds;
      if (is_cancelled(options.progress)) return plan;
      if (!next || next->quality.degenerate > 0) break;
      found = checker.pairs(*next);
      current = std::move(*next);
      if (found.empty()) {
        pairs = 0;
        report.changed = true;
        report.weight = weight;
        plan.triangulation = std::move(current);
        return plan;
      }
    }
  }
  return plan;
}

}  // namespace holefill::detail
