#include "island_meshes.h"

#include <algorithm>
#include <cmath>

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
