#include "island_meshes.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "test_meshes.h"

namespace holefill::testing {

Mesh make_blob(int levels, const RadiusFunction& radius) {
  Mesh mesh = make_icosphere(levels);
  for (const auto v : mesh.vertices()) {
    const Point direction = mesh.point(v).normalized();
    mesh.set_point(v, radius(direction) * direction);
  }
  return mesh;
}

bool Cap::contains(const Point& p) const {
  const double cosine = OpenMesh::dot(p.normalized(), axis.normalized());
  return std::acos(std::clamp(cosine, -1.0, 1.0)) < angle;
}

Mesh cut_around_islands(const Mesh& closed, const Cap& cut, const std::vector<Cap>& islands) {
  return without_isolated_vertices(without_faces(closed, [&](const Point& centroid) {
    return cut.contains(centroid) &&
           std::none_of(islands.begin(), islands.end(),
                        [&](const Cap& island) { return island.contains(centroid); });
  }));
}

Mesh tube_cut_in_two(int around, int along, int cut_begin, int cut_end) {
  Mesh tube;
  std::vector<VertexHandle> at;
  for (int j = 0; j <= along; ++j) {
    for (int i = 0; i < around; ++i) {
      const double angle = 2.0 * std::numbers::pi * i / around;
      at.push_back(tube.add_vertex(Point(std::cos(angle), std::sin(angle), 0.1 * j)));
    }
  }
  for (int j = 0; j < along; ++j) {
    if (j >= cut_begin && j < cut_end) continue;
    for (int i = 0; i < around; ++i) {
      const auto a = at[j * around + i], b = at[j * around + (i + 1) % around];
      const auto c = at[(j + 1) * around + (i + 1) % around], d = at[(j + 1) * around + i];
      tube.add_face(a, b, c);
      tube.add_face(a, c, d);
    }
  }
  return without_isolated_vertices(tube);
}

Mesh without_isolated_vertices(const Mesh& mesh) {
  Mesh compact;
  std::vector<VertexHandle> moved(mesh.n_vertices());
  for (const auto v : mesh.vertices()) {
    if (!mesh.is_isolated(v)) moved[v.idx()] = compact.add_vertex(mesh.point(v));
  }
  for (const auto f : mesh.faces()) {
    std::vector<VertexHandle> corners;
    for (const auto v : mesh.fv_range(f)) corners.push_back(moved[v.idx()]);
    compact.add_face(corners);
  }
  return compact;
}

long euler_characteristic(const Mesh& mesh) {
  long used_vertices = 0;
  for (const auto v : mesh.vertices()) used_vertices += mesh.is_isolated(v) ? 0 : 1;
  return used_vertices - static_cast<long>(mesh.n_edges()) + static_cast<long>(mesh.n_faces());
}

}  // namespace holefill::testing
