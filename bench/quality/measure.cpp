#include "measure.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <unordered_set>

namespace holefill::quality {
namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

// Closest point to p on triangle (a, b, c), by the region of the triangle's plane p projects
// into: a corner, an edge, or the inside (barycentric coordinates from the dot products).
Point closest_on_triangle(const Point& p, const Point& a, const Point& b, const Point& c) {
  const Point ab = b - a, ac = c - a, ap = p - a;
  const double d1 = OpenMesh::dot(ab, ap), d2 = OpenMesh::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Point bp = p - b;
  const double d3 = OpenMesh::dot(ab, bp), d4 = OpenMesh::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + ab * (d1 / (d1 - d3));
  const Point cp = p - c;
  const double d5 = OpenMesh::dot(ab, cp), d6 = OpenMesh::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  }
  const double denominator = va + vb + vc;
  if (!(denominator > 0.0)) return a;  // degenerate triangle: its corners were checked above
  return a + ab * (vb / denominator) + ac * (vc / denominator);
}

double angle_at(const Point& corner, const Point& a, const Point& b) {
  const Point u = a - corner, v = b - corner;
  return std::atan2(OpenMesh::cross(u, v).norm(), OpenMesh::dot(u, v));
}

double dihedral(const Mesh& mesh, HalfedgeHandle h) {
  const FaceHandle f0 = mesh.face_handle(h), f1 = mesh.opposite_face_handle(h);
  if (!f0.is_valid() || !f1.is_valid()) return kNaN;
  const Point n0 = mesh.calc_face_normal(f0), n1 = mesh.calc_face_normal(f1);
  return std::atan2(OpenMesh::cross(n0, n1).norm(), OpenMesh::dot(n0, n1)) * kDegrees;
}

double percentile(std::vector<double> values, double fraction) {
  if (values.empty()) return kNaN;
  std::sort(values.begin(), values.end());
  // Nearest rank.
  const auto rank = static_cast<std::size_t>(std::ceil(fraction * values.size()));
  return values[std::clamp<std::size_t>(rank, 1, values.size()) - 1];
}

double mean(const std::vector<double>& values) {
  if (values.empty()) return kNaN;
  double sum = 0.0;
  for (const double v : values) sum += v;
  return sum / static_cast<double>(values.size());
}

double maximum(const std::vector<double>& values) {
  return values.empty() ? kNaN : *std::max_element(values.begin(), values.end());
}

std::vector<FaceHandle> all_faces(const Mesh& mesh) {
  std::vector<FaceHandle> faces;
  for (const auto f : mesh.faces()) faces.push_back(f);
  return faces;
}

}  // namespace

Truth::Truth(const Mesh& closed) : Truth(closed, all_faces(closed)) {}

Truth::Truth(const Mesh& mesh, const std::vector<FaceHandle>& faces) {
  Point low(std::numeric_limits<double>::infinity()), high(-low);
  for (const auto v : mesh.vertices()) {
    low.minimize(mesh.point(v));
    high.maximize(mesh.point(v));
  }
  diagonal_ = (high - low).norm();
  for (const auto f : faces) {
    auto fv = mesh.cfv_iter(f);
    Triangle t;
    t.a = mesh.point(*fv);
    t.b = mesh.point(*++fv);
    t.c = mesh.point(*++fv);
    t.center = (t.a + t.b + t.c) / 3.0;
    t.radius =
        std::max({(t.a - t.center).norm(), (t.b - t.center).norm(), (t.c - t.center).norm()});
    triangles_.push_back(t);
  }
}

double Truth::distance(const Point& p) const {
  if (triangles_.empty()) return std::numeric_limits<double>::infinity();
  return (p - nearest(p)).norm();
}

Point Truth::nearest(const Point& p) const {
  // Start from the triangle whose centre is nearest, then look only at triangles whose ball
  // could hold something nearer.
  if (triangles_.empty()) return p;
  std::size_t start = 0;
  double nearest_center = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < triangles_.size(); ++i) {
    const double d = (p - triangles_[i].center).sqrnorm();
    if (d < nearest_center) nearest_center = d, start = i;
  }
  const Triangle& first = triangles_[start];
  Point best = closest_on_triangle(p, first.a, first.b, first.c);
  double best_distance = (p - best).norm();
  for (const auto& t : triangles_) {
    if ((p - t.center).norm() - t.radius >= best_distance) continue;
    const Point q = closest_on_triangle(p, t.a, t.b, t.c);
    if ((p - q).norm() < best_distance) best = q, best_distance = (p - q).norm();
  }
  return best;
}

Quality measure(const Mesh& filled, const std::vector<FilledHole>& holes, const Truth& truth) {
  Quality quality;
  std::vector<double> distances, min_angles, patch_edges, surrounding_edges, boundary_dihedrals,
      patch_dihedrals;
  std::size_t valence6 = 0;
  for (const auto& hole : holes) {
    quality.new_vertices += hole.new_vertices.size();
    quality.faces += hole.faces.size();
    std::unordered_set<int> faces;
    for (const auto f : hole.faces) faces.insert(f.idx());
    auto in_patch = [&](FaceHandle f) { return f.is_valid() && faces.count(f.idx()) > 0; };

    for (const auto v : hole.new_vertices) {
      distances.push_back(truth.distance(filled.point(v)));
      valence6 += filled.valence(v) == 6;
    }
    std::unordered_set<int> boundary_edges, inner_edges;
    for (std::size_t i = 0; i < hole.boundary.size(); ++i) {
      const auto h =
          filled.find_halfedge(hole.boundary[i], hole.boundary[(i + 1) % hole.boundary.size()]);
      if (!h.is_valid()) continue;
      boundary_edges.insert(filled.edge_handle(h).idx());
      boundary_dihedrals.push_back(dihedral(filled, h));
    }
    for (const auto f : hole.faces) {
      auto fv = filled.cfv_iter(f);
      const Point &a = filled.point(*fv), &b = filled.point(*++fv), &c = filled.point(*++fv);
      distances.push_back(truth.distance((a + b + c) / 3.0));
      min_angles.push_back(std::min({angle_at(a, b, c), angle_at(b, c, a), angle_at(c, a, b)}) *
                           kDegrees);
      for (const auto h : filled.fh_range(f)) {
        const int e = filled.edge_handle(h).idx();
        if (boundary_edges.count(e) || !inner_edges.insert(e).second) continue;
        patch_edges.push_back(filled.calc_edge_length(h));
        if (in_patch(filled.opposite_face_handle(h)))
          patch_dihedrals.push_back(dihedral(filled, h));
      }
    }
    for (const auto v : hole.boundary) {
      for (const auto h : filled.voh_range(v)) {
        if (!in_patch(filled.face_handle(h)) || !in_patch(filled.opposite_face_handle(h))) {
          if (!boundary_edges.count(filled.edge_handle(h).idx())) {
            surrounding_edges.push_back(filled.calc_edge_length(h));
          }
        }
      }
    }
  }
  quality.mean_distance = mean(distances) / truth.diagonal();
  quality.max_distance = maximum(distances) / truth.diagonal();
  quality.min_angle_p5 = percentile(min_angles, 0.05);
  quality.min_angle = percentile(min_angles, 0.0);
  quality.valence6_share = quality.new_vertices ? static_cast<double>(valence6) /
                                                      static_cast<double>(quality.new_vertices)
                                                : kNaN;
  quality.edge_length_ratio = mean(patch_edges) / mean(surrounding_edges);
  quality.mean_boundary_dihedral = mean(boundary_dihedrals);
  quality.max_boundary_dihedral = maximum(boundary_dihedrals);
  quality.max_dihedral = std::max(maximum(patch_dihedrals), quality.max_boundary_dihedral);
  return quality;
}

}  // namespace holefill::quality
