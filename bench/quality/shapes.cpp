#include "shapes.h"

#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <vector>

#include "test_meshes.h"

namespace holefill::quality {

Mesh make_icosphere(int levels) {
  return make_star_shape(
      levels, [](const Point&) { return 1.0; }, Point(1.0, 1.0, 1.0));
}

Mesh make_star_shape(int levels, const std::function<double(const Point&)>& radius,
                     const Point& axis_scale) {
  Mesh mesh = testing::make_icosphere(levels);  // the unit sphere, pushed out along each ray
  for (const auto v : mesh.vertices()) {
    const Point q = mesh.point(v) * radius(mesh.point(v));
    mesh.set_point(v, Point(q[0] * axis_scale[0], q[1] * axis_scale[1], q[2] * axis_scale[2]));
  }
  return mesh;
}

Mesh make_torus(double major, double minor, int around, int tube) {
  Mesh mesh;
  for (int i = 0; i < around; ++i) {
    const double u = 2.0 * std::numbers::pi * i / around;
    for (int j = 0; j < tube; ++j) {
      const double v = 2.0 * std::numbers::pi * j / tube;
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
