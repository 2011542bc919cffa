#include "cgal_bridge.h"

#include "cgal_fill.h"

namespace holefill::quality {
namespace {

// The same points and faces, same indices.
PlainMesh plain_copy(const Mesh& mesh) {
  PlainMesh plain;
  for (const auto v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    plain.points.push_back({p[0], p[1], p[2]});
  }
  for (const auto f : mesh.faces()) {
    auto fv = mesh.cfv_iter(f);
    const int a = fv->idx(), b = (++fv)->idx(), c = (++fv)->idx();
    plain.faces.push_back({a, b, c});
  }
  return plain;
}

}  // namespace

Mesh fill_with_cgal(const Mesh& cut, const std::vector<Hole>& loops,
                    std::vector<FilledHole>& patches, std::size_t& unfaired) {
  PlainMesh plain = plain_copy(cut);
  std::vector<std::array<int, 2>> hole_edges;
  for (const auto& loop : loops) {
    hole_edges.push_back({loop.vertices[0].idx(), loop.vertices[1].idx()});
  }
  const CgalFill filled = cgal_fill(plain, hole_edges);
  Mesh mesh;
  for (const auto& p : filled.mesh.points) mesh.add_vertex(Point(p[0], p[1], p[2]));
  for (const auto& f : filled.mesh.faces) {
    mesh.add_face(VertexHandle(f[0]), VertexHandle(f[1]), VertexHandle(f[2]));
  }
  for (std::size_t i = 0; i < loops.size(); ++i) {
    FilledHole patch{loops[i].vertices, {}, {}};
    for (const int f : filled.patches[i].faces) patch.faces.emplace_back(f);
    for (const int v : filled.patches[i].new_vertices) patch.new_vertices.emplace_back(v);
    unfaired += filled.patches[i].faired ? 0 : 1;
    patches.push_back(std::move(patch));
  }
  return mesh;
}

bool fair_with_cgal(Mesh& mesh, const std::vector<FilledHole>& patches) {
  PlainMesh plain = plain_copy(mesh);
  bool all = true;
  for (const auto& patch : patches) {
    std::vector<int> vertices;
    for (const auto v : patch.new_vertices) vertices.push_back(v.idx());
    all = cgal_fair(plain, vertices) && all;
  }
  for (const auto v : mesh.vertices()) {
    const auto& p = plain.points[v.idx()];
    mesh.set_point(v, Point(p[0], p[1], p[2]));
  }
  return all;
}

}  // namespace holefill::quality
