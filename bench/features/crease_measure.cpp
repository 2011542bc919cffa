#include "crease_measure.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <unordered_set>
#include <vector>

#include "exact_intersections.h"
#include "holefill/holes.h"
#include "test_meshes.h"

namespace holefill::features {
namespace {

const double kNotANumber = std::numeric_limits<double>::quiet_NaN();
constexpr int kCoverSubdivisions = 4;  // 15 points a cut-away triangle
constexpr int kCreaseSamples = 4;      // points along each crease edge

double face_angle_degrees(const Mesh& mesh, HalfedgeHandle h) {
  const FaceHandle f0 = mesh.face_handle(h), f1 = mesh.opposite_face_handle(h);
  if (!f0.is_valid() || !f1.is_valid()) return kNotANumber;
  const Point n0 = mesh.calc_face_normal(f0), n1 = mesh.calc_face_normal(f1);
  return std::atan2(OpenMesh::cross(n0, n1).norm(), OpenMesh::dot(n0, n1)) * 180.0 /
         std::numbers::pi;
}

double distance_to_segment(const Point& p, const Point& a, const Point& b) {
  const Point ab = b - a;
  const double t = std::clamp(OpenMesh::dot(p - a, ab) / std::max(ab.sqrnorm(), 1e-300), 0.0, 1.0);
  return (p - (a + ab * t)).norm();
}

// The sharpest dihedral (degrees) among `edges` of `mesh` within `reach` of p; 0 when no edge is
// that near.
double sharpest_near(const Mesh& mesh, const std::vector<HalfedgeHandle>& edges, const Point& p,
                     double reach) {
  double sharpest = 0.0;
  for (const auto h : edges) {
    const Point a = mesh.point(mesh.from_vertex_handle(h)),
                b = mesh.point(mesh.to_vertex_handle(h));
    if (distance_to_segment(p, a, b) > reach) continue;
    const double angle = face_angle_degrees(mesh, h);
    if (!std::isnan(angle)) sharpest = std::max(sharpest, angle);
  }
  return sharpest;
}

// One halfedge of each edge between two of the faces: the patch's own edges, not those it
// shares with the mesh around the hole.
std::vector<HalfedgeHandle> inner_edges(const Mesh& mesh, const std::vector<FaceHandle>& faces) {
  std::unordered_set<int> in_patch, seen;
  for (const auto f : faces) in_patch.insert(f.idx());
  std::vector<HalfedgeHandle> edges;
  for (const auto f : faces) {
    for (const auto h : mesh.fh_range(f)) {
      const FaceHandle other = mesh.opposite_face_handle(h);
      if (!other.is_valid() || !in_patch.count(other.idx())) continue;
      if (seen.insert(mesh.edge_handle(h).idx()).second) edges.push_back(h);
    }
  }
  return edges;
}

// Cover: the cut-away faces sampled on a barycentric grid, each sample's distance to the fill
// (distances / `diagonal`).
void measure_cover(const Mesh& closed, const quality::CutHole& hole, const quality::Truth& fill,
                   double diagonal, FeatureQuality& q) {
  double weighted = 0.0, area = 0.0;
  q.cover_max = 0.0;
  for (const auto f : hole.removed_faces) {
    auto fv = closed.cfv_iter(f);
    const Point a = closed.point(*fv), b = closed.point(*++fv), c = closed.point(*++fv);
    const double face_area = 0.5 * OpenMesh::cross(b - a, c - a).norm();
    double sum = 0.0;
    int count = 0;
    for (int i = 0; i <= kCoverSubdivisions; ++i) {
      for (int j = 0; i + j <= kCoverSubdivisions; ++j, ++count) {
        const Point p = a + (b - a) * (double(i) / kCoverSubdivisions) +
                        (c - a) * (double(j) / kCoverSubdivisions);
        const double d = fill.distance(p);
        sum += d;
        q.cover_max = std::max(q.cover_max, d);
      }
    }
    weighted += face_area * sum / count;
    area += face_area;
  }
  q.cover_mean = (area > 0.0 ? weighted / area : kNotANumber) / diagonal;
  q.cover_max /= diagonal;
}

// The truth's crease edges inside the hole, sampled; their distance to the fill and how sharp
// the fill and the truth are near each sample.
void measure_crease(const Mesh& closed, const quality::CutHole& hole, const Mesh& filled,
                    const quality::FilledHole& patch, const quality::Truth& fill, double diagonal,
                    FeatureQuality& q) {
  std::unordered_set<int> removed;
  for (const auto f : hole.removed_faces) removed.insert(f.idx());
  const double reach = 0.5 * quality::mean_edge_length(closed);
  const auto fill_edges = inner_edges(filled, patch.faces);
  const auto truth_edges = inner_edges(closed, hole.removed_faces);
  double distance_sum = 0.0, fill_angle_sum = 0.0, truth_angle_sum = 0.0;
  q.crease_max = 0.0;
  for (const auto h : truth_edges) {
    const FaceHandle f0 = closed.face_handle(h), f1 = closed.opposite_face_handle(h);
    if (!removed.count(f0.idx()) || !removed.count(f1.idx())) continue;
    if (!(face_angle_degrees(closed, h) > kSharpDegrees)) continue;
    const Point a = closed.point(closed.from_vertex_handle(h));
    const Point b = closed.point(closed.to_vertex_handle(h));
    for (int s = 0; s < kCreaseSamples; ++s) {
      const Point p = a + (b - a) * ((s + 0.5) / kCreaseSamples);
      const Point on_fill = fill.nearest(p);
      const double d = (p - on_fill).norm();
      distance_sum += d;
      q.crease_max = std::max(q.crease_max, d);
      // Around the fill's point nearest the sample, wherever that is: the angle apart from the
      // distance.
      fill_angle_sum += sharpest_near(filled, fill_edges, on_fill, reach);
      truth_angle_sum += sharpest_near(closed, truth_edges, p, reach);
      ++q.crease_samples;
    }
  }
  if (q.crease_samples == 0) {
    q.crease_mean = q.crease_max = q.crease_dihedral = q.truth_dihedral = kNotANumber;
    return;
  }
  const double n = static_cast<double>(q.crease_samples);
  q.crease_mean = distance_sum / n / diagonal;
  q.crease_max /= diagonal;
  q.crease_dihedral = fill_angle_sum / n;
  q.truth_dihedral = truth_angle_sum / n;
}

}  // namespace

FeatureQuality measure_feature_fill(const Mesh& closed, const quality::Truth& truth,
                                    const quality::CutHole& hole, const Mesh& filled,
                                    const quality::FilledHole& patch, bool check_intersections) {
  FeatureQuality q;
  q.patch = quality::measure(filled, {patch}, truth);
  const quality::Truth fill(filled, patch.faces);
  measure_cover(closed, hole, fill, truth.diagonal(), q);
  measure_crease(closed, hole, filled, patch, fill, truth.diagonal(), q);
  q.manifold = testing::is_oriented_manifold(filled);
  q.closed = find_holes(filled).empty();
  q.intersections =
      check_intersections ? testing::exact_patch_intersections(filled, patch.faces) : 0;
  return q;
}

}  // namespace holefill::features
