#include "holefill/stats.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_set>
#include <vector>

#include "geometry.h"
#include "holefill/triangulate.h"
#include "safe_scale.h"
#include "sets_by_lowest.h"

namespace holefill {
namespace {
constexpr double kDegrees = 180.0 / std::numbers::pi;

// The power of two the patch's points are divided by when measured: 0, or where its largest
// coordinate lies beyond safe_scale.h's range, that coordinate's exponent. Squared lengths
// overflow beyond about 1e77 (the fill is scaled, but its stats are measured at the mesh's own
// scale: at 1e78 every normal was zero and the angles read 90 and 180 degrees) and underflow
// below about 1e-77; the angles do not depend on the scale.
int measuring_exponent(const Mesh& mesh, const Patch& patch) {
  double largest = 0.0;
  for (const auto f : patch.faces) {
    for (const auto v : mesh.fv_range(f)) {
      largest = std::max(largest, detail::SafeScale::largest_coordinate(mesh.point(v)));
    }
  }
  return detail::SafeScale::leaves_alone(largest) ? 0 : std::ilogb(largest);
}

Point scaled_down(const Point& p, int exponent) {
  return Point(std::ldexp(p[0], -exponent), std::ldexp(p[1], -exponent),
               std::ldexp(p[2], -exponent));
}

// The face's unit normal, from its points scaled down by 2^exponent where that is not 0.
Point face_normal(const Mesh& mesh, FaceHandle f, int exponent) {
  if (exponent == 0) return mesh.calc_face_normal(f);
  auto fv = mesh.cfv_iter(f);
  const Point a = scaled_down(mesh.point(*fv), exponent);
  const Point b = scaled_down(mesh.point(*++fv), exponent);
  const Point c = scaled_down(mesh.point(*++fv), exponent);
  const Point n = OpenMesh::cross(c - b, a - b);
  const double length = n.norm();
  return length > 0.0 ? n / length : n;
}

}  // namespace

PatchStats patch_stats(const Mesh& mesh, const Patch& patch) {
  PatchStats stats;
  stats.new_vertices = patch.new_vertices.size();
  stats.new_faces = patch.faces.size();
  for (const auto v : patch.new_vertices) ++stats.valence_histogram[mesh.valence(v)];

  const int exponent = measuring_exponent(mesh, patch);
  std::unordered_set<int> edges;
  double min_angle = patch.faces.empty() ? 0.0 : std::numbers::pi, angle_sum = 0.0;
  for (const auto f : patch.faces) {
    auto fv = mesh.cfv_iter(f);
    const Point a = scaled_down(mesh.point(*fv), exponent);
    const Point b = scaled_down(mesh.point(*++fv), exponent);
    const Point c = scaled_down(mesh.point(*++fv), exponent);
    const geometry::TriangleMeasures m = geometry::measure_triangle(a, b, c);
    min_angle = std::min(min_angle, m.min_angle);
    angle_sum += m.min_angle;
    stats.area += std::ldexp(m.area, 2 * exponent);
    for (const auto e : mesh.fe_range(f)) edges.insert(e.idx());
  }
  double max_dihedral = 0.0;
  for (const int id : edges) {
    const EdgeHandle e(id);
    if (mesh.is_boundary(e)) continue;
    const auto f0 = mesh.face_handle(mesh.halfedge_handle(e, 0));
    const auto f1 = mesh.face_handle(mesh.halfedge_handle(e, 1));
    max_dihedral =
        std::max(max_dihedral, geometry::angle_between_normals(face_normal(mesh, f0, exponent),
                                                               face_normal(mesh, f1, exponent)));
  }
  stats.min_angle_deg = min_angle * kDegrees;
  stats.mean_min_angle_deg =
      patch.faces.empty() ? 0.0 : angle_sum / static_cast<double>(patch.faces.size()) * kDegrees;
  stats.max_dihedral_deg = max_dihedral * kDegrees;
  return stats;
}

std::map<int, std::size_t> valence_histogram(const Mesh& mesh) {
  std::map<int, std::size_t> histogram;
  for (const auto v : mesh.vertices()) ++histogram[mesh.valence(v)];
  return histogram;
}

std::vector<int> component_labels(const Mesh& mesh) {
  std::vector<int> label(mesh.n_vertices(), -1);
  for (const auto v : mesh.vertices()) label[v.idx()] = v.idx();
  detail::number_sets_by_lowest(label, [&mesh](auto join) {
    for (const auto e : mesh.edges()) {
      const HalfedgeHandle h = mesh.halfedge_handle(e, 0);
      join(mesh.from_vertex_handle(h).idx(), mesh.to_vertex_handle(h).idx());
    }
  });
  return label;
}

std::size_t connected_components(const Mesh& mesh) {
  const std::vector<int> label = component_labels(mesh);
  return label.empty()
             ? 0
             : static_cast<std::size_t>(*std::max_element(label.begin(), label.end()) + 1);
}

SurfaceCounts surface_counts(const Mesh& mesh) {
  const std::vector<int> label = component_labels(mesh);
  // Labels are numbered in order of first vertex, so a label seen for the first time is the
  // largest so far: count the labels of used vertices that exceed every earlier one.
  SurfaceCounts counts;
  int highest_used = -1;
  for (const auto v : mesh.vertices()) {
    if (mesh.is_isolated(v)) {
      ++counts.unused_vertices;
    } else if (label[v.idx()] > highest_used) {
      highest_used = label[v.idx()];
      ++counts.components;
    }
  }
  return counts;
}

}  // namespace holefill
