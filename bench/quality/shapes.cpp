#include "shapes.h"

#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace holefill::quality {

Mesh make_icosphere(int levels) {
  return make_star_shape(
      levels, [](const Point&) { return 1.0; }, Point(1.0, 1.0, 1.0));
}

Mesh make_star_shape(int levels, const std::function<double(const Point&)>& radius,
                     const Point& axis_scale) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Point> points{{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                            {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                            {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<int, 3>> faces{
      {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (auto& p : points) p.normalize();
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> midpoints;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      if (const auto found = midpoints.find(key); found != midpoints.end()) return found->second;
      points.push_back(((points[a] + points[b]) * 0.5).normalized());
      return midpoints[key] = static_cast<int>(points.size()) - 1;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto& f : faces) {
      const int ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
      finer.push_back({f[0], ab, ca});
      finer.push_back({f[1], bc, ab});
      finer.push_back({f[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    faces = std::move(finer);
  }
  Mesh mesh;
  for (const auto& p : points) {
    const Point q = p * radius(p);
    mesh.add_vertex(Point(q[0] * axis_scale[0], q[1] * axis_scale[1], q[2] * axis_scale[2]));
  }
  for (const auto& f : faces) {
    mesh.add_face(VertexHandle(f[0]), VertexHandle(f[1]), VertexHandle(f[2]));
  }
  return mesh;
}

Mesh make_torus(double major, double minor, int around, int tube) {
  Mesh mesh;
  for (int i = 0; i < around; ++i) {
    const double u = 2.0 * M_PI * i / around;
    for (int j = 0; j < tube; ++j) {
      const double v = 2.0 * M_PI * j / tube;
      const double ring = major + minor * std::cos(v);
      mesh.add_vertex(Point(ring * std::cos(u), ring * std::sin(u), minor * std::sin(v)));
    }
  }
  auto at = [&](int i, int j) { return VertexHandle(((i % around) * tube) + (j % tube)); };
  for (int i = 0; i < around; ++i) {
    for (int j = 0; j < tube; ++j) {
      // Counter-clockwise seen from outside: u grows to the left of v's direction.
      mesh.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      mesh.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  }
  return mesh;
}

}  // namespace holefill::quality
