#include "exact_intersections.h"

#include <gmpxx.h>

#include <algorithm>

namespace holefill::testing {
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

std::size_t exact_patch_intersections(const Mesh& mesh, const std::vector<FaceHandle>& patch) {
  auto corners = [&](FaceHandle f) {
    std::array<Point, 3> c;
    int i = 0;
    for (const auto v : mesh.fv_range(f)) c[i++ % 3] = mesh.point(v);
    return c;
  };
  auto apart = [](const std::array<Point, 3>& a, const std::array<Point, 3>& b) {
    for (int axis = 0; axis < 3; ++axis) {
      const auto [a0, a1] = std::minmax({a[0][axis], a[1][axis], a[2][axis]});
      const auto [b0, b1] = std::minmax({b[0][axis], b[1][axis], b[2][axis]});
      if (a1 < b0 || b1 < a0) return true;
    }
    return false;
  };
  std::vector<int> position(mesh.n_faces(), -1);
  for (std::size_t i = 0; i < patch.size(); ++i) position[patch[i].idx()] = static_cast<int>(i);
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < patch.size(); ++i) {
    const auto a = corners(patch[i]);
    for (const auto f : mesh.faces()) {
      // Pairs within the patch once, from their first face.
      if (position[f.idx()] >= 0 && position[f.idx()] <= static_cast<int>(i)) continue;
      const auto b = corners(f);
      if (!apart(a, b) && exactly_intersect(a, b)) ++pairs;
    }
  }
  return pairs;
}

}  // namespace holefill::testing
