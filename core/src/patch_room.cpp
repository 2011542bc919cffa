#include "patch_room.h"

#include <algorithm>
#include <cmath>
#include <new>

#include "mesh_room.h"

namespace holefill::detail {

PatchRoom& PatchRoom::operator+=(const PatchRoom& other) {
  vertices += other.vertices;
  edges += other.edges;
  faces += other.faces;
  return *this;
}

PatchRoom patch_room(const Mesh& mesh, const Hole& hole, const PolygonTriangulation& triangulation,
                     bool refined) {
  const std::size_t boundary = hole.size();
  std::size_t faces = triangulation.triangles.size();
  const double length = hole.mean_surrounding_edge_length;
  if (refined && length > 0.0) {
    double area = 0.0;
    for (const auto& [i, m, k] : triangulation.triangles) {
      const Point a = mesh.point(hole.vertices[i]);
      area +=
          0.5 * ((mesh.point(hole.vertices[m]) - a) % (mesh.point(hole.vertices[k]) - a)).norm();
    }
    const double triangle_area = std::sqrt(3.0) / 4.0 * length * length;
    const double density_faces = area / triangle_area;
    // A huge or non-finite estimate (a degenerate surrounding) reserves nothing extra.
    if (std::isfinite(density_faces) && density_faces < 1e9) {
      faces = std::max(faces, static_cast<std::size_t>(density_faces));
    }
  }
  // A disk with b boundary edges and v inner vertices has b - 2 + 2v faces and b - 3 + 3v inner
  // edges.
  const std::size_t inner_vertices = faces + 2 > boundary ? (faces + 2 - boundary) / 2 : 0;
  const std::size_t inner_edges = boundary >= 3 ? boundary - 3 + 3 * inner_vertices : 0;
  return {inner_vertices, inner_edges, faces};
}

void reserve_patch_room(Mesh& mesh, const PatchRoom& added) {
  const auto beyond_room = [](std::size_t count, std::size_t more) { return more > count / 8; };
  if (!beyond_room(mesh.n_vertices(), added.vertices) &&
      !beyond_room(mesh.n_edges(), added.edges) && !beyond_room(mesh.n_faces(), added.faces)) {
    return;
  }
  // At most twice the elements, as growing would make it: an estimate far too large (a flat hole
  // among tiny faces) must not ask for more memory than the fill would use. Reserving only saves
  // a copy, so a failure to get the room leaves the arrays to grow as they would have.
  const auto grown = [](std::size_t count, std::size_t more) {
    return with_room(count + std::min(more, count));
  };
  try {
    mesh.reserve(grown(mesh.n_vertices(), added.vertices), grown(mesh.n_edges(), added.edges),
                 grown(mesh.n_faces(), added.faces));
  } catch (const std::bad_alloc&) {
  }
}

}  // namespace holefill::detail
