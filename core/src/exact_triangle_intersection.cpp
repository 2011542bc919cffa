#include "exact_triangle_intersection.h"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace holefill::detail {
namespace {

using Q3 = std::array<mpq_class, 3>;

Q3 exact(const Point& p) { return {mpq_class(p[0]), mpq_class(p[1]), mpq_class(p[2])}; }
Q3 minus(const Q3& a, const Q3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Q3 cross(const Q3& a, const Q3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
mpq_class dot(const Q3& a, const Q3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
bool is_zero(const Q3& a) { return sgn(a[0]) == 0 && sgn(a[1]) == 0 && sgn(a[2]) == 0; }

struct ExactTriangle {
  std::array<Q3, 3> p;
  Q3 normal;
  explicit ExactTriangle(const std::array<Point, 3>& corners) {
    for (int i = 0; i < 3; ++i) p[i] = exact(corners[i]);
    normal = cross(minus(p[1], p[0]), minus(p[2], p[0]));
  }
  // Sign of x's side of the plane.
  int side(const Q3& x) const { return sgn(dot(normal, minus(x, p[0]))); }
};

// Coplanar triangles: their interiors overlap unless a side's line leaves the other triangle in
// the closed half-plane away from the first's third corner.
bool separated_by_a_side(const ExactTriangle& t, const ExactTriangle& other) {
  for (int e = 0; e < 3; ++e) {
    const Q3& from = t.p[e];
    const Q3 along = minus(t.p[(e + 1) % 3], from);
    auto side = [&](const Q3& x) { return sgn(dot(cross(along, minus(x, from)), t.normal)); };
    const int inner = side(t.p[(e + 2) % 3]);
    if (std::all_of(other.p.begin(), other.p.end(),
                    [&](const Q3& x) { return side(x) * inner <= 0; })) {
      return true;
    }
  }
  return false;
}

// The section of `t` by the plane of `other`, as an interval of the parameter dot(direction, x)
// along the planes' common line, and whether it passes through t's interior.
struct Section {
  mpq_class low, high;
  bool through_interior = false;
};
Section section(const ExactTriangle& t, const ExactTriangle& other, const Q3& direction) {
  std::array<mpq_class, 3> s;
  int on_plane = 0;
  for (int i = 0; i < 3; ++i) {
    s[i] = dot(other.normal, minus(t.p[i], other.p[0]));
    on_plane += sgn(s[i]) == 0;
  }
  std::vector<mpq_class> at;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (sgn(s[i]) == 0) at.push_back(dot(direction, t.p[i]));
    if (sgn(s[i]) * sgn(s[j]) < 0) {
      const mpq_class u = s[i] / (s[i] - s[j]);
      Q3 x;
      for (int a = 0; a < 3; ++a) x[a] = t.p[i][a] + u * (t.p[j][a] - t.p[i][a]);
      at.push_back(dot(direction, x));
    }
  }
  Section result;
  result.low = *std::min_element(at.begin(), at.end());
  result.high = *std::max_element(at.begin(), at.end());
  result.through_interior = on_plane <= 1 && result.low < result.high;
  return result;
}

bool straddles(const ExactTriangle& t, const ExactTriangle& other) {
  int below = 0, above = 0;
  for (const auto& x : t.p) {
    const int side = other.side(x);
    below += side < 0;
    above += side > 0;
  }
  return below < 3 && above < 3;
}

// The floating-point filter. orient(a, b, c, d) is the determinant of (b - a, c - a, d - a); its
// rounding error is below 1e-14 times the permanent (the same sum over absolute values), far above
// the textbook bound of about 8e-16 for this evaluation. A sign is certain when the determinant
// exceeds that bound and nothing underflowed (a permanent too small to trust goes to rationals).
int certain_orientation(const Point& a, const Point& b, const Point& c, const Point& d) {
  const Point u = b - a, v = c - a, w = d - a;
  const double x1 = u[1] * v[2], x2 = u[2] * v[1], y1 = u[2] * v[0], y2 = u[0] * v[2];
  const double z1 = u[0] * v[1], z2 = u[1] * v[0];
  const double det = w[0] * (x1 - x2) + w[1] * (y1 - y2) + w[2] * (z1 - z2);
  const double permanent = std::abs(w[0]) * (std::abs(x1) + std::abs(x2)) +
                           std::abs(w[1]) * (std::abs(y1) + std::abs(y2)) +
                           std::abs(w[2]) * (std::abs(z1) + std::abs(z2));
  if (!(permanent > 1e-250) || !std::isfinite(permanent)) return 0;
  const double bound = 1e-14 * permanent;
  return det > bound ? 1 : det < -bound ? -1 : 0;
}

// `other` meets `t`'s plane only at corners it shares with `t` (the same coordinates): its other
// corners lie, certainly, strictly on one side. Then the two touch at most along what they share,
// which does not count; so do triangles wholly on one side. Neighbours of a patch triangle share a
// corner or a side with it, and most are settled here.
bool certainly_beside(const std::array<Point, 3>& t, const std::array<Point, 3>& other) {
  int side = 0;
  for (const Point& corner : other) {
    if (corner == t[0] || corner == t[1] || corner == t[2]) continue;
    const int s = certain_orientation(t[0], t[1], t[2], corner);
    if (s == 0 || (side != 0 && s != side)) return false;
    side = s;
  }
  return side != 0;
}

// orient2d's certain sign in the plane of coordinates (x, y) = (axes.first, axes.second): 1 when
// c lies to the left of a -> b, -1 to the right, 0 when too close to tell in floating point.
int certain_orientation2(const Point& a, const Point& b, const Point& c, std::pair<int, int> axes) {
  const auto [x, y] = axes;
  const double l = (b[x] - a[x]) * (c[y] - a[y]), r = (b[y] - a[y]) * (c[x] - a[x]);
  const double permanent = std::abs(l) + std::abs(r);
  if (!(permanent > 1e-250) || !std::isfinite(permanent)) return 0;
  const double bound = 1e-14 * permanent;
  return l - r > bound ? 1 : l - r < -bound ? -1 : 0;
}

// Some side of `t`, in the projection along `axes`, has every corner of `other` that `t` does not
// share certainly beyond its line (away from t's third corner). The projection of t must be
// certainly non-degenerate, so that it is one to one on t: the triangles then meet at most at
// shared corners.
bool separated_by_a_side_in(const std::array<Point, 3>& t, const std::array<Point, 3>& other,
                            std::pair<int, int> axes) {
  const int turn = certain_orientation2(t[0], t[1], t[2], axes);
  if (turn == 0) return false;
  for (int e = 0; e < 3; ++e) {
    const Point &from = t[e], &to = t[(e + 1) % 3];
    const bool apart = std::all_of(other.begin(), other.end(), [&](const Point& p) {
      return p == from || p == to || certain_orientation2(from, to, p, axes) == -turn;
    });
    if (apart) return true;
  }
  return false;
}

// The two triangles' projections on the coordinate plane that `a` projects onto best are certainly
// apart but for shared corners, by a side of either: then so are the triangles. This settles the
// neighbours that lie in or near one plane (a flat hole's patch and its surroundings), where the
// plane test cannot tell.
bool certainly_apart_in_projection(const std::array<Point, 3>& a, const std::array<Point, 3>& b) {
  const Point n = OpenMesh::cross(a[1] - a[0], a[2] - a[0]);
  const double x = std::abs(n[0]), y = std::abs(n[1]), z = std::abs(n[2]);
  const std::pair<int, int> axes = x >= y && x >= z ? std::pair(1, 2)
                                   : y >= z         ? std::pair(2, 0)
                                                    : std::pair(0, 1);
  if (separated_by_a_side_in(a, b, axes)) return true;
  // b's projection along a's axes need not be one to one: only a corner sharing a's may meet a.
  return certain_orientation2(b[0], b[1], b[2], axes) != 0 && separated_by_a_side_in(b, a, axes);
}

}  // namespace

bool exactly_intersect(const std::array<Point, 3>& a, const std::array<Point, 3>& b) {
  const ExactTriangle t1(a), t2(b);
  if (is_zero(t1.normal) || is_zero(t2.normal)) return false;
  if (std::all_of(t2.p.begin(), t2.p.end(), [&](const Q3& x) { return t1.side(x) == 0; })) {
    return !separated_by_a_side(t1, t2) && !separated_by_a_side(t2, t1);
  }
  if (!straddles(t1, t2) || !straddles(t2, t1)) return false;
  const Q3 direction = cross(t1.normal, t2.normal);
  const Section s1 = section(t1, t2, direction), s2 = section(t2, t1, direction);
  return (s1.through_interior || s2.through_interior) && s1.low < s2.high && s2.low < s1.high;
}

bool exactly_intersect_filtered(const std::array<Point, 3>& a, const std::array<Point, 3>& b) {
  return !certainly_beside(a, b) && !certainly_beside(b, a) &&
         !certainly_apart_in_projection(a, b) && exactly_intersect(a, b);
}

}  // namespace holefill::detail
