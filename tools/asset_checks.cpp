#include "asset_checks.h"

#include <algorithm>
#include <functional>
#include <stdexcept>

namespace make_assets {

Topology analyze(const Mesh& m) {
  const HalfedgeMap h = halfedges(m);  // throws on a repeated directed edge
  std::vector<int> boundaryNext(m.points.size(), -1);
  std::vector<int> faceCount(m.points.size(), 0);
  for (const Face& f : m.faces) {
    if (f[0] == f[1] || f[1] == f[2] || f[2] == f[0]) throw std::runtime_error("degenerate face");
    for (int v : f) ++faceCount[v];
  }
  for (const auto& [edge, face] : h) {
    if (!isBoundary(h, edge.first, edge.second)) continue;
    if (boundaryNext[edge.first] >= 0) throw std::runtime_error("pinched boundary vertex");
    boundaryNext[edge.first] = edge.second;
  }
  // Every vertex must see one fan of faces: walk around it across edges and make sure the
  // walk visits all of its faces.
  for (int v = 0; v < static_cast<int>(m.points.size()); ++v) {
    if (faceCount[v] == 0) throw std::runtime_error("unreferenced vertex");
    // Start from the boundary edge if there is one, so the walk covers the whole fan.
    int start = -1;
    if (boundaryNext[v] >= 0) {
      start = h.at({v, boundaryNext[v]});
    } else {
      for (int f = 0; f < static_cast<int>(m.faces.size()) && start < 0; ++f)
        if (std::ranges::find(m.faces[f], v) != m.faces[f].end()) start = f;
    }
    int visited = 0;
    int f = start;
    do {
      ++visited;
      const Face& face = m.faces[f];
      const int i = static_cast<int>(std::ranges::find(face, v) - face.begin());
      const int prev = face[(i + 2) % 3];  // edge (prev, v) in this face; next face has (v, prev)
      auto it = h.find({v, prev});
      f = (it == h.end()) ? -1 : it->second;
    } while (f >= 0 && f != start);
    if (visited != faceCount[v]) throw std::runtime_error("vertex with several fans of faces");
  }
  Topology t;
  const std::vector<int> comp = faceComponents(m, std::vector<bool>(m.faces.size(), true));
  t.components = m.faces.empty() ? 0 : 1 + *std::ranges::max_element(comp);
  std::vector<bool> seen(m.points.size(), false);
  for (int v = 0; v < static_cast<int>(m.points.size()); ++v) {
    if (boundaryNext[v] < 0 || seen[v]) continue;
    int length = 0;
    for (int w = v; !seen[w]; w = boundaryNext[w]) {
      seen[w] = true;
      ++length;
    }
    t.loops.push_back(length);
  }
  std::ranges::sort(t.loops, std::greater{});
  return t;
}

double coneVolume(const Mesh& m, Vec3 o) {
  double v = 0;
  for (const Face& f : m.faces)
    v += dot(m.points[f[0]] - o, cross(m.points[f[1]] - o, m.points[f[2]] - o)) / 6;
  return v;
}

double distanceToBoundary(const Mesh& m, Vec3 p) {
  const HalfedgeMap h = halfedges(m);
  double d = INFINITY;
  for (const auto& [edge, face] : h)
    if (isBoundary(h, edge.first, edge.second)) d = std::min(d, norm(m.points[edge.first] - p));
  return d;
}

}  // namespace make_assets
