#include "hole_cutting.h"

#include <algorithm>
#include <stdexcept>

namespace make_assets {

Mesh cutHole(const Mesh& mesh, const WavyBall& region) {
  const int nf = static_cast<int>(mesh.faces.size());
  int seed = 0;
  for (int f = 1; f < nf; ++f) {
    if (norm(centroid(mesh, mesh.faces[f]) - region.center) <
        norm(centroid(mesh, mesh.faces[seed]) - region.center))
      seed = f;
  }
  std::vector<bool> inside(nf);
  for (int f = 0; f < nf; ++f) inside[f] = region.contains(centroid(mesh, mesh.faces[f]));
  if (!inside[seed]) throw std::runtime_error("hole region does not contain its centre");
  const std::vector<int> piece = faceComponents(mesh, inside);

  const HalfedgeMap before = halfedges(mesh);
  std::vector<bool> keep(nf);
  for (int f = 0; f < nf; ++f) keep[f] = !(inside[f] && piece[f] == piece[seed]);

  for (bool changed = true; changed;) {
    changed = false;
    HalfedgeMap now;
    for (int f = 0; f < nf; ++f)
      if (keep[f])
        for (int i = 0; i < 3; ++i) now[{mesh.faces[f][i], mesh.faces[f][(i + 1) % 3]}] = f;
    auto newBoundary = [&](int a, int b) {
      return isBoundary(now, a, b) && !isBoundary(before, a, b);
    };
    std::vector<int> boundaryOut(mesh.points.size(), 0);
    for (const auto& [edge, face] : now)
      if (isBoundary(now, edge.first, edge.second)) ++boundaryOut[edge.first];
    std::vector<bool> drop(nf, false);
    for (int f = 0; f < nf; ++f) {
      if (!keep[f]) continue;
      const Face& t = mesh.faces[f];
      int count = 0;
      for (int i = 0; i < 3; ++i) count += newBoundary(t[i], t[(i + 1) % 3]) ? 1 : 0;
      if (count >= 2) drop[f] = true;
      for (int v : t)
        if (boundaryOut[v] > 1) drop[f] = true;
    }
    for (int f = 0; f < nf; ++f) {
      if (drop[f]) {
        keep[f] = false;
        changed = true;
      }
    }
    // Largest component only (drops islands left inside the hole).
    const std::vector<int> comp = faceComponents(mesh, keep);
    std::vector<int> size(nf, 0);
    for (int f = 0; f < nf; ++f)
      if (keep[f]) ++size[comp[f]];
    const int largest = static_cast<int>(std::ranges::max_element(size) - size.begin());
    for (int f = 0; f < nf; ++f) {
      if (keep[f] && comp[f] != largest) {
        keep[f] = false;
        changed = true;
      }
    }
  }
  return subMesh(mesh, keep);
}

std::pair<Vec3, Vec3> surfacePoint(const Mesh& m, Vec3 p) {
  int best = 0;
  for (int v = 1; v < static_cast<int>(m.points.size()); ++v)
    if (norm(m.points[v] - p) < norm(m.points[best] - p)) best = v;
  Vec3 n;
  for (const Face& f : m.faces)
    if (std::ranges::find(f, best) != f.end())
      n = n + cross(m.points[f[1]] - m.points[f[0]], m.points[f[2]] - m.points[f[0]]);
  return {m.points[best], normalized(n)};
}

}  // namespace make_assets
