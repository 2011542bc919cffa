#include "cgal_fill.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/fair.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>

#include <iterator>
#include <tuple>

namespace holefill::quality {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using SurfaceVertex = SurfaceMesh::Vertex_index;
using SurfaceFace = SurfaceMesh::Face_index;

}  // namespace

CgalFill cgal_fill(const PlainMesh& cut, const std::vector<std::array<int, 2>>& hole_edges) {
  SurfaceMesh surface;
  for (const auto& p : cut.points) surface.add_vertex(Kernel::Point_3(p[0], p[1], p[2]));
  for (const auto& f : cut.faces) {
    surface.add_face(SurfaceVertex(f[0]), SurfaceVertex(f[1]), SurfaceVertex(f[2]));
  }

  CgalFill result;
  for (const auto& edge : hole_edges) {
    CgalPatch patch;
    const auto [border, found] =
        CGAL::halfedge(SurfaceVertex(edge[0]), SurfaceVertex(edge[1]), surface);
    if (found && CGAL::is_border(border, surface)) {
      std::vector<SurfaceFace> faces;
      std::vector<SurfaceVertex> vertices;
      patch.faired = std::get<0>(CGAL::Polygon_mesh_processing::triangulate_refine_and_fair_hole(
          surface, border, std::back_inserter(faces), std::back_inserter(vertices)));
      for (const auto f : faces) patch.faces.push_back(static_cast<int>(f.idx()));
      for (const auto v : vertices) patch.new_vertices.push_back(static_cast<int>(v.idx()));
    }
    result.patches.push_back(std::move(patch));
  }

  // Surface_mesh appends vertices and faces and nothing was removed, so indices carry over.
  for (const auto v : surface.vertices()) {
    const auto& p = surface.point(v);
    result.mesh.points.push_back({p.x(), p.y(), p.z()});
  }
  for (const auto f : surface.faces()) {
    std::array<int, 3> corners{};
    int c = 0;
    for (const auto v : CGAL::vertices_around_face(surface.halfedge(f), surface)) {
      if (c < 3) corners[c++] = static_cast<int>(v.idx());
    }
    result.mesh.faces.push_back(corners);
  }
  return result;
}

bool cgal_fair(PlainMesh& mesh, const std::vector<int>& vertices) {
  SurfaceMesh surface;
  for (const auto& p : mesh.points) surface.add_vertex(Kernel::Point_3(p[0], p[1], p[2]));
  for (const auto& f : mesh.faces) {
    surface.add_face(SurfaceVertex(f[0]), SurfaceVertex(f[1]), SurfaceVertex(f[2]));
  }
  std::vector<SurfaceVertex> movable;
  for (const int v : vertices) movable.emplace_back(v);
  if (!CGAL::Polygon_mesh_processing::fair(surface, movable)) return false;
  for (const int v : vertices) {
    const auto& p = surface.point(SurfaceVertex(v));
    mesh.points[v] = {p.x(), p.y(), p.z()};
  }
  return true;
}

}  // namespace holefill::quality
