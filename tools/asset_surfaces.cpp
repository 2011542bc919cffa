#include "asset_surfaces.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

namespace make_assets {

namespace {

constexpr double kPi = std::numbers::pi;

// The implicit heart (x^2 + 9/4 y^2 + z^2 - 1)^3 - x^2 z^3 - 9/80 y^2 z^3 = 0 (z up, y the
// thin front-back direction). Negative inside. It is star-shaped around the origin.
double heartFunction(Vec3 p) {
  const double s = p.x * p.x + 2.25 * p.y * p.y + p.z * p.z - 1;
  const double z3 = p.z * p.z * p.z;
  return s * s * s - p.x * p.x * z3 - 9.0 / 80.0 * p.y * p.y * z3;
}

}  // namespace

Mesh geodesicSphere(int k) {
  const double g = (1 + std::sqrt(5.0)) / 2;
  const std::vector<Vec3> ico = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0},
                                 {0, -1, g}, {0, 1, g}, {0, -1, -g}, {0, 1, -g},
                                 {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  const std::vector<Face> icoFaces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                      {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                      {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                      {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  Mesh m;
  // A point of the subdivision is sum(w_i * corner_i) / k with integer weights w_i summing to
  // k. The weights, keyed by corner index, name the point exactly, so points on shared edges
  // and corners are found again from the neighbouring face.
  std::map<std::vector<std::pair<int, int>>, int> index;
  auto point = [&](const Face& corners, int wa, int wb, int wc) {
    std::vector<std::pair<int, int>> key;
    for (auto [c, w] : {std::pair{corners[0], wa}, {corners[1], wb}, {corners[2], wc}})
      if (w > 0) key.emplace_back(c, w);
    std::ranges::sort(key);
    auto [it, fresh] = index.emplace(key, static_cast<int>(m.points.size()));
    if (fresh) {
      Vec3 p;
      for (auto [c, w] : key) p = p + static_cast<double>(w) * ico[c];
      m.points.push_back(normalized(p));
    }
    return it->second;
  };
  for (const Face& t : icoFaces) {
    // Row i runs from corner a (i = 0) to the edge bc (i = k); j steps along it towards c.
    auto at = [&](int i, int j) { return point(t, k - i, i - j, j); };
    for (int i = 0; i < k; ++i) {
      for (int j = 0; j <= i; ++j) {
        m.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        if (j < i) m.faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    }
  }
  return m;
}

Vec3 projectOntoHeart(Vec3 d) {
  double inner = 0, outer = 0.01;
  while (heartFunction(outer * d) < 0) {
    inner = outer;
    outer += 0.01;
  }
  for (int i = 0; i < 60; ++i) {
    const double mid = (inner + outer) / 2;
    (heartFunction(mid * d) < 0 ? inner : outer) = mid;
  }
  return ((inner + outer) / 2) * d;
}

Mesh torus(double R, double r, int n, int m) {
  Mesh t;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      const double u = 2 * kPi * i / n, v = 2 * kPi * j / m;
      t.points.push_back({(R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
                          r * std::sin(v)});
    }
  }
  auto id = [&](int i, int j) { return (i % n) * m + (j % m); };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      t.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      t.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return t;
}

Mesh terrain(int n) {
  Mesh t;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      const double x = -1 + 2.0 * j / n, y = -1 + 2.0 * i / n;
      const double z = 0.12 * std::sin(3 * x + 0.5) * std::cos(2 * y) +
                       0.05 * std::sin(5 * x + 4 * y) + 0.08 * std::exp(-4 * (x * x + y * y));
      t.points.push_back({x, y, z});
    }
  }
  auto id = [&](int i, int j) { return i * (n + 1) + j; };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const int a = id(i, j), b = id(i, j + 1), c = id(i + 1, j + 1), d = id(i + 1, j);
      if ((i + j) % 2 == 0) {
        t.faces.push_back({a, b, c});
        t.faces.push_back({a, c, d});
      } else {
        t.faces.push_back({a, b, d});
        t.faces.push_back({b, c, d});
      }
    }
  }
  return t;
}

}  // namespace make_assets
