#include "holefill/features.h"

#include <cmath>
#include <numbers>

#include "feature_junctions.h"

namespace holefill {
namespace {

// A line is traced this many edges outward: enough for a tangent and its change, and no farther
// than the fans a fill made apart from the mesh copies (patch_apart.h: the boundary's neighbours'
// fans), so that a line is the same there.
constexpr int kTraceEdges = 2;
// A line needs at least this many sharp edges in a row to count: a lone sharp edge at a noisy
// scan's boundary is no feature.
constexpr int kMinTracedEdges = 2;
// Tracing stops where the sharpest continuation turns by more than this (a corner of the part).
constexpr double kMaxTraceTurnDegrees = 40.0;
// A boundary vertex lies on a line continued when it is this close to it, as a share of its
// distance from the line's end.
constexpr double kOnLineShare = 0.02;

Point normalized_or_zero(const Point& p) {
  const double length = p.norm();
  return length > 0.0 ? p / length : Point(0.0, 0.0, 0.0);
}

// The line from `start` through its sharp edge to `next`, continued along the sharp edge that
// turns least at each vertex, up to kTraceEdges edges or a boundary vertex or a sharp turn;
// `at_corner` tells whether it stopped where other sharp edges turn away (a corner of the part).
std::vector<Point> trace_line(const Mesh& mesh, VertexHandle start, VertexHandle next,
                              double angle_degrees, bool& at_corner) {
  std::vector<Point> traced{mesh.point(start), mesh.point(next)};
  at_corner = false;
  const double min_cos = std::cos(kMaxTraceTurnDegrees * std::numbers::pi / 180.0);
  VertexHandle previous = start, current = next;
  while (static_cast<int>(traced.size()) <= kTraceEdges && !mesh.is_boundary(current)) {
    const Point heading = normalized_or_zero(mesh.point(current) - mesh.point(previous));
    VertexHandle best;
    double best_cos = min_cos;
    for (const auto h : mesh.voh_range(current)) {
      const VertexHandle to = mesh.to_vertex_handle(h);
      if (to == previous || !is_sharp_edge(mesh, mesh.edge_handle(h), angle_degrees)) continue;
      at_corner = true;
      const double turn =
          OpenMesh::dot(heading, normalized_or_zero(mesh.point(to) - mesh.point(current)));
      if (turn > best_cos) {
        best_cos = turn;
        best = to;
      }
    }
    if (!best.is_valid()) break;
    at_corner = false;
    previous = current;
    current = best;
    traced.push_back(mesh.point(current));
  }
  return traced;
}

// The unit tangent at traced[0] of the quadratic through traced[0..2] (chord-length
// parameters, exact for points on a line or, to second order, on a circle), pointing away from
// the traced line, i.e. into the hole.
Point inward_tangent(const std::vector<Point>& traced) {
  if (traced.size() < 3) return normalized_or_zero(traced[0] - traced[1]);
  const double h1 = (traced[1] - traced[0]).norm();
  const double h2 = h1 + (traced[2] - traced[1]).norm();
  // Derivative at t = 0 of the Lagrange quadratic through (0, p0), (h1, p1), (h2, p2).
  const Point outward = traced[0] * (-(h1 + h2) / (h1 * h2)) + traced[1] * (h2 / (h1 * (h2 - h1))) -
                        traced[2] * (h1 / (h2 * (h2 - h1)));
  return normalized_or_zero(-outward);
}

// Where the quadratic through traced[0..2] (chord-length parameters, outward) puts the point
// `step` before traced[0], i.e. the line continued into the hole by that length.
Point extrapolated(const std::vector<Point>& traced, double step) {
  if (traced.size() < 3) return traced[0] + normalized_or_zero(traced[0] - traced[1]) * step;
  const double h1 = (traced[1] - traced[0]).norm();
  const double h2 = h1 + (traced[2] - traced[1]).norm();
  const double t = -step;
  return traced[0] * ((t - h1) * (t - h2) / (h1 * h2)) +
         traced[1] * (t * (t - h2) / (h1 * (h1 - h2))) +
         traced[2] * (t * (t - h1) / (h2 * (h2 - h1)));
}

// A feature line may run on along the hole's boundary (the hole took the faces on one side of
// the crease only): while a neighbour of the entry on the loop lies where the line continues to
// (within kOnLineShare of the step), that neighbour becomes the entry.
void follow_along_boundary(const Mesh& mesh, const Hole& hole, FeatureLine& line) {
  const int n = static_cast<int>(hole.size());
  for (int steps = 0; steps < n; ++steps) {
    bool moved = false;
    for (const int next : {(line.entry + 1) % n, (line.entry + n - 1) % n}) {
      const Point& p = mesh.point(hole.vertices[next]);
      const double step = (p - line.traced[0]).norm();
      if (!(step > 0.0) || (extrapolated(line.traced, step) - p).norm() > kOnLineShare * step)
        continue;
      line.traced.insert(line.traced.begin(), p);
      line.entry = next;
      line.vertex = hole.vertices[next];
      moved = true;
      break;
    }
    if (!moved) return;
  }
}

// The curvature (1 / radius) of the circle through traced[0..2]; 0 with fewer points.
double curvature_of(const std::vector<Point>& traced) {
  if (traced.size() < 3) return 0.0;
  const Point u = traced[0] - traced[1], w = traced[2] - traced[1];
  const double span = (traced[2] - traced[0]).norm();
  return span > 0.0 ? 2.0 * OpenMesh::cross(u, w).norm() / (u.norm() * w.norm() * span) : 0.0;
}

// Whether the loop is a plain boundary loop: every halfedge real, no vertex twice.
bool is_plain_loop(const Hole& hole) {
  if (hole.pinched || hole.repeated_vertices > 0 || hole.size() < 3) return false;
  for (const auto h : hole.halfedges) {
    if (!h.is_valid()) return false;
  }
  return true;
}

}  // namespace

bool is_sharp_edge(const Mesh& mesh, EdgeHandle edge, double angle_degrees) {
  if (mesh.is_boundary(edge)) return false;
  const Point n0 = mesh.calc_face_normal(mesh.face_handle(mesh.halfedge_handle(edge, 0)));
  const Point n1 = mesh.calc_face_normal(mesh.face_handle(mesh.halfedge_handle(edge, 1)));
  const double angle = std::atan2(OpenMesh::cross(n0, n1).norm(), OpenMesh::dot(n0, n1));
  return angle > angle_degrees * std::numbers::pi / 180.0;
}

HoleFeatures find_hole_features(const Mesh& mesh, const Hole& hole, const FeatureOptions& options) {
  HoleFeatures features;
  if (!(options.angle_degrees > 0.0) || !is_plain_loop(hole)) return features;
  for (int i = 0; i < static_cast<int>(hole.vertices.size()); ++i) {
    const VertexHandle v = hole.vertices[i];
    for (const auto h : mesh.voh_range(v)) {
      if (!is_sharp_edge(mesh, mesh.edge_handle(h), options.angle_degrees)) continue;
      FeatureLine line;
      line.entry = i;
      line.vertex = v;
      bool at_corner = false;
      line.traced = trace_line(mesh, v, mesh.to_vertex_handle(h), options.angle_degrees, at_corner);
      // One edge is enough where the line ends at a corner of the part a step away.
      if (static_cast<int>(line.traced.size()) < kMinTracedEdges + 1 && !at_corner) continue;
      follow_along_boundary(mesh, hole, line);
      line.direction = inward_tangent(line.traced);
      line.curvature = curvature_of(line.traced);
      for (std::size_t k = 1; k < line.traced.size(); ++k) {
        line.edge_length += (line.traced[k] - line.traced[k - 1]).norm();
      }
      line.edge_length /= static_cast<double>(line.traced.size() - 1);
      features.lines.push_back(std::move(line));
    }
  }
  if (!features.lines.empty()) detail::match_feature_lines(mesh, hole, features);
  return features;
}

}  // namespace holefill
