#include "feature_junctions.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>

namespace holefill::detail {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
// Each line of a corner points at the meeting point within this angle.
constexpr double kCornerAngle = 10.0 * kDegree;
// The lines of a corner must not be nearly parallel: the least-squares system's smallest
// eigenvalue (each line adds at most 1 to it) at least this.
constexpr double kCornerConditioning = 0.1;
// A straight crease: both lines point along the chord within this angle.
constexpr double kStraightAngle = 10.0 * kDegree;
// A curved crease (a circular arc turns both ends by the same angle, in one plane): each line
// within kCurvedAngle of the chord, the sum of the two ends' directions of travel within
// kCurvedAsymmetry of the chord, and the two tangents and the chord within kCurvedTwist of one
// plane.
constexpr double kCurvedAngle = 50.0 * kDegree;
constexpr double kCurvedAsymmetry = 10.0 * kDegree;
const double kCurvedTwist = std::sin(10.0 * kDegree);
// ... and each line's own curvature within this factor of the arc's.
constexpr double kCurvatureFactor = 2.0;
// More lines than this entering one hole is no part's edge but a sharp-edged mess.
constexpr std::size_t kMostLines = 12;
// Samples of a crease's curve to measure its length.
constexpr int kLengthSamples = 64;

double angle_between(const Point& u, const Point& v) {
  return std::atan2(OpenMesh::cross(u, v).norm(), OpenMesh::dot(u, v));
}

// The point nearest the lines (least squares over their squared distances), when the lines are
// not nearly parallel.
std::optional<Point> nearest_point(const std::vector<const FeatureLine*>& lines) {
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (const FeatureLine* line : lines) {
    const Eigen::Vector3d t(line->direction[0], line->direction[1], line->direction[2]);
    const Eigen::Vector3d p(line->traced[0][0], line->traced[0][1], line->traced[0][2]);
    const Eigen::Matrix3d across = Eigen::Matrix3d::Identity() - t * t.transpose();
    a += across;
    b += across * p;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(a);
  if (!(eigen.eigenvalues()[0] > kCornerConditioning)) return std::nullopt;
  const Eigen::Vector3d x = a.ldlt().solve(b);
  return Point(x[0], x[1], x[2]);
}

// The largest angle between a line's direction and the way from its entry to `corner`; pi when
// the corner is behind a line's entry.
double corner_miss(const std::vector<const FeatureLine*>& lines, const Point& corner) {
  double worst = 0.0;
  for (const FeatureLine* line : lines) {
    worst = std::max(worst, angle_between(line->direction, corner - line->traced[0]));
  }
  return worst;
}

struct HoleExtent {
  Point centroid;
  double radius = 0.0;
};

HoleExtent extent_of(const Mesh& mesh, const Hole& hole) {
  HoleExtent extent{hole.centroid, 0.0};
  for (const auto v : hole.vertices) {
    extent.radius = std::max(extent.radius, (mesh.point(v) - hole.centroid).norm());
  }
  return extent;
}

// The best corner among the unused lines: the triple that points at its nearest point most
// closely, with every other unused line that points there too. Nothing when no triple does.
std::optional<FeatureJunction> best_corner(const HoleFeatures& features,
                                           const std::vector<bool>& used,
                                           const HoleExtent& extent) {
  const auto& lines = features.lines;
  const int n = static_cast<int>(lines.size());
  std::optional<FeatureJunction> best;
  double best_miss = kCornerAngle;
  const auto consider = [&](const std::vector<int>& group) {
    std::vector<const FeatureLine*> members;
    for (const int l : group) {
      if (used[l]) return;
      members.push_back(&lines[l]);
    }
    const auto point = nearest_point(members);
    if (!point || (*point - extent.centroid).norm() > extent.radius) return;
    const double miss = corner_miss(members, *point);
    if (miss >= best_miss) return;
    best_miss = miss;
    best = FeatureJunction{group, true, *point, {}};
  };
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      for (int k = j + 1; k < n; ++k) consider({i, j, k});
    }
  }
  if (!best) return best;
  for (int m = 0; m < n; ++m) {
    if (used[m] || std::count(best->lines.begin(), best->lines.end(), m)) continue;
    if (corner_miss({&lines[m]}, best->corner_point) < kCornerAngle) best->lines.push_back(m);
  }
  std::sort(best->lines.begin(), best->lines.end(),
            [&](int a, int b) { return lines[a].entry < lines[b].entry; });
  return best;
}

// How badly lines a and b point at each other as the ends of one crease; nothing when they do
// not (neither straight nor an even curve).
std::optional<double> crease_misfit(const FeatureLine& a, const FeatureLine& b) {
  if (a.entry == b.entry) return std::nullopt;
  const Point chord = b.traced[0] - a.traced[0];
  if (!(chord.norm() > 0.0)) return std::nullopt;
  const double at_a = angle_between(a.direction, chord), at_b = angle_between(b.direction, -chord);
  const double worst = std::max(at_a, at_b);
  if (worst < kStraightAngle) return worst;
  // An arc's end tangents lie mirrored about the chord's normal plane: their sum runs along the
  // chord (an S-bend's does not).
  const double asymmetry = angle_between(a.direction - b.direction, chord);
  const double twist =
      std::abs(OpenMesh::dot(a.direction, OpenMesh::cross(b.direction, chord / chord.norm())));
  // And the lines curve as that arc does (two straight lines at an angle meet at a corner).
  const double arc = 2.0 * std::sin(0.5 * (at_a + at_b)) / chord.norm();
  const auto bends_so = [arc](double curvature) {
    return curvature > arc / kCurvatureFactor && curvature < arc * kCurvatureFactor;
  };
  if (worst < kCurvedAngle && asymmetry < kCurvedAsymmetry && twist < kCurvedTwist &&
      bends_so(a.curvature) && bends_so(b.curvature)) {
    return worst + asymmetry;
  }
  return std::nullopt;
}

// The cubic Hermite curve from a (leaving along a.direction) to b (arriving against
// b.direction), its tangents as long as a circular arc's with the same turn would have them,
// so that a crease on a circle stays close to it and a straight one is a uniform segment.
struct Hermite {
  Point p0, p1, m0, m1;
  Point at(double s) const {
    const double s2 = s * s, s3 = s2 * s;
    return p0 * (2 * s3 - 3 * s2 + 1) + m0 * (s3 - 2 * s2 + s) + p1 * (-2 * s3 + 3 * s2) +
           m1 * (s3 - s2);
  }
};

Hermite crease_curve(const FeatureLine& a, const FeatureLine& b) {
  const Point p0 = a.traced[0], p1 = b.traced[0];
  const double turn = angle_between(a.direction, -b.direction);
  const double c = std::cos(turn / 4.0);
  const double length = (p1 - p0).norm() / (c * c);
  return {p0, p1, a.direction * length, -b.direction * length};
}

std::vector<Point> crease_path(const FeatureLine& a, const FeatureLine& b) {
  const Hermite curve = crease_curve(a, b);
  double length = 0.0;
  for (int i = 1; i <= kLengthSamples; ++i) {
    length +=
        (curve.at(double(i) / kLengthSamples) - curve.at(double(i - 1) / kLengthSamples)).norm();
  }
  const double spacing = 0.5 * (a.edge_length + b.edge_length);
  const long segments = std::max(1L, std::lround(length / spacing));
  std::vector<Point> path;
  for (long i = 1; i < segments; ++i) path.push_back(curve.at(double(i) / double(segments)));
  return path;
}

std::vector<Point> segment_path(const Point& from, const Point& to, double spacing) {
  const long segments = std::max(1L, std::lround((to - from).norm() / spacing));
  std::vector<Point> path;
  for (long i = 1; i < segments; ++i) path.push_back(from + (to - from) * (double(i) / segments));
  return path;
}

void route_corner(const HoleFeatures& features, FeatureJunction& corner) {
  double spacing = 0.0;
  for (const int l : corner.lines) spacing += features.lines[l].edge_length;
  spacing /= static_cast<double>(corner.lines.size());
  for (const int l : corner.lines) {
    corner.paths.push_back(segment_path(features.lines[l].traced[0], corner.corner_point, spacing));
  }
}

// Pairs the unused lines into creases, best fits first.
void match_creases(HoleFeatures& features, std::vector<bool>& used) {
  struct Candidate {
    double misfit;
    int a, b;
  };
  std::vector<Candidate> candidates;
  const int n = static_cast<int>(features.lines.size());
  for (int a = 0; a < n; ++a) {
    for (int b = a + 1; b < n; ++b) {
      if (used[a] || used[b]) continue;
      if (const auto misfit = crease_misfit(features.lines[a], features.lines[b])) {
        candidates.push_back({*misfit, a, b});
      }
    }
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& x, const Candidate& y) { return x.misfit < y.misfit; });
  for (const auto& c : candidates) {
    if (used[c.a] || used[c.b]) continue;
    used[c.a] = used[c.b] = true;
    FeatureJunction crease{{c.a, c.b}, false, Point(0.0, 0.0, 0.0), {}};
    crease.paths.push_back(crease_path(features.lines[c.a], features.lines[c.b]));
    features.junctions.push_back(std::move(crease));
  }
}

std::string unmatched_note(const HoleFeatures& features, const std::vector<bool>& used) {
  for (std::size_t i = 0; i < used.size(); ++i) {
    if (used[i]) continue;
    const FeatureLine& line = features.lines[i];
    const Point& p = line.traced[0];
    std::ostringstream at;
    at << p[0] << ", " << p[1] << ", " << p[2];
    return "the feature line entering at (" + at.str() + ") (boundary position " +
           std::to_string(line.entry) +
           ") has no partner across the hole (no line pointing back at it, no corner where it "
           "meets two others)";
  }
  return {};
}

}  // namespace

void match_feature_lines(const Mesh& mesh, const Hole& hole, HoleFeatures& features) {
  features.junctions.clear();
  if (features.lines.size() > kMostLines) {
    features.note = std::to_string(features.lines.size()) +
                    " feature lines enter the hole, more than the " + std::to_string(kMostLines) +
                    " that are matched across one";
    return;
  }
  std::vector<bool> used(features.lines.size(), false);
  const HoleExtent extent = extent_of(mesh, hole);
  while (auto corner = best_corner(features, used, extent)) {
    for (const int l : corner->lines) used[l] = true;
    route_corner(features, *corner);
    features.junctions.push_back(std::move(*corner));
  }
  match_creases(features, used);
  features.note = unmatched_note(features, used);
  if (!features.note.empty()) features.junctions.clear();
}

}  // namespace holefill::detail
