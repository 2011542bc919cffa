#include "cad_shapes.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "cad_parts.h"

namespace holefill::features {
namespace {

using testing::CellSolid;
using testing::grid_lines;

// Grid lines from `from` in the given steps.
std::vector<double> lines_from(double from, const std::vector<std::pair<double, int>>& steps) {
  std::vector<double> lines = grid_lines(steps);
  for (double& x : lines) x += from;
  return lines;
}

// Connects two concentric rings (vertex lists ordered counter-clockwise seen from +z, each
// closed) with triangles, walking both by angle: always advancing the ring whose next vertex
// comes first. `up`: the faces look toward +z (else -z).
void zip_rings(Mesh& mesh, const std::vector<VertexHandle>& inner,
               const std::vector<VertexHandle>& outer, bool up) {
  auto angle = [&](const std::vector<VertexHandle>& ring, std::size_t i) {
    // Angle of the i-th vertex, unwrapped past the ring's end.
    const Point p = mesh.point(ring[i % ring.size()]);
    double a = std::atan2(p[1], p[0]);
    const Point p0 = mesh.point(ring[0]);
    const double a0 = std::atan2(p0[1], p0[0]);
    while (a < a0 - 1e-9) a += 2.0 * std::numbers::pi;
    if (i >= ring.size()) a += 2.0 * std::numbers::pi;
    return a;
  };
  auto face = [&](VertexHandle a, VertexHandle b, VertexHandle c) {
    if (up) {
      mesh.add_face(a, b, c);
    } else {
      mesh.add_face(a, c, b);
    }
  };
  std::size_t i = 0, o = 0;
  while (i < inner.size() || o < outer.size()) {
    const bool advance_outer =
        i >= inner.size() || (o < outer.size() && angle(outer, o + 1) <= angle(inner, i + 1));
    if (advance_outer) {
      face(inner[i % inner.size()], outer[o % outer.size()], outer[(o + 1) % outer.size()]);
      ++o;
    } else {
      face(inner[i % inner.size()], outer[o % outer.size()], inner[(i + 1) % inner.size()]);
      ++i;
    }
  }
}

// A flat cap at height z whose outer ring is `rim` (radius `radius`): rings of fewer vertices
// toward a centre vertex, spaced like the rim's vertices.
void add_cap(Mesh& mesh, const std::vector<VertexHandle>& rim, double radius, double z, bool up) {
  const int around = static_cast<int>(rim.size());
  const double spacing = 2.0 * std::numbers::pi * radius / around;
  const int rings = std::max(1, static_cast<int>(std::lround(radius / spacing)));
  std::vector<VertexHandle> outer = rim;
  for (int k = rings - 1; k >= 1; --k) {
    const int count = std::max(6, around * k / rings);
    const double r = radius * k / rings;
    std::vector<VertexHandle> ring;
    for (int n = 0; n < count; ++n) {
      // Half a step of twist per ring keeps the triangles between rings from lining up.
      const double a = 2.0 * std::numbers::pi * (n + 0.5 * ((rings - k) % 2)) / count;
      ring.push_back(mesh.add_vertex(Point(r * std::cos(a), r * std::sin(a), z)));
    }
    zip_rings(mesh, ring, outer, up);
    outer = std::move(ring);
  }
  const VertexHandle centre = mesh.add_vertex(Point(0.0, 0.0, z));
  for (std::size_t n = 0; n < outer.size(); ++n) {
    if (up) {
      mesh.add_face(centre, outer[n], outer[(n + 1) % outer.size()]);
    } else {
      mesh.add_face(centre, outer[(n + 1) % outer.size()], outer[n]);
    }
  }
}

}  // namespace

Mesh make_box(double half, int segments) {
  const auto lines = lines_from(-half, {{2.0 * half / segments, segments}});
  return surface_of(CellSolid{lines, lines, lines, [](int, int, int) { return true; }});
}

Mesh make_cylinder(double radius, double half_height, int around) {
  Mesh mesh;
  const double spacing = 2.0 * std::numbers::pi * radius / around;
  const int rows = std::max(1, static_cast<int>(std::lround(2.0 * half_height / spacing)));
  std::vector<std::vector<VertexHandle>> circles;
  for (int j = 0; j <= rows; ++j) {
    const double z = -half_height + 2.0 * half_height * j / rows;
    std::vector<VertexHandle> circle;
    for (int i = 0; i < around; ++i) {
      const double a = 2.0 * std::numbers::pi * i / around;
      circle.push_back(mesh.add_vertex(Point(radius * std::cos(a), radius * std::sin(a), z)));
    }
    circles.push_back(std::move(circle));
  }
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < around; ++i) {
      const int next = (i + 1) % around;
      // Outward: counter-clockwise seen from outside, angle growing to the right of +z.
      mesh.add_face(circles[j][i], circles[j][next], circles[j + 1][next]);
      mesh.add_face(circles[j][i], circles[j + 1][next], circles[j + 1][i]);
    }
  }
  add_cap(mesh, circles.back(), radius, half_height, true);
  add_cap(mesh, circles.front(), radius, -half_height, false);
  return mesh;
}

Mesh make_rounded_box(double inner, double fillet, int segments, int fillet_segments) {
  const auto lines = lines_from(-inner - fillet, {{fillet / fillet_segments, fillet_segments},
                                                  {2.0 * inner / segments, segments},
                                                  {fillet / fillet_segments, fillet_segments}});
  Mesh mesh = surface_of(CellSolid{lines, lines, lines, [](int, int, int) { return true; }});
  for (const auto v : mesh.vertices()) {
    // The box's point moved to `fillet` from its nearest point on the inner box, along the way
    // from that point: flat faces stay (their points are `fillet` straight out), edges and
    // corners bend into quarter cylinders and eighth spheres.
    const Point p = mesh.point(v);
    Point q;
    for (int axis = 0; axis < 3; ++axis) q[axis] = std::clamp(p[axis], -inner, inner);
    mesh.set_point(v, q + (p - q).normalized() * fillet);
  }
  return mesh;
}

Mesh make_step_block(int per_unit) {
  const auto lines = lines_from(0.0, {{1.0 / per_unit, 2 * per_unit}});
  const auto depth = lines_from(0.0, {{1.0 / per_unit, per_unit}});
  return surface_of(CellSolid{lines, depth, lines, [&](int i, int, int k) {
                                return !(lines[i] >= 1.0 - 1e-9 && lines[k] >= 1.0 - 1e-9);
                              }});
}

}  // namespace holefill::features
