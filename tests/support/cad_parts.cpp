#include "cad_parts.h"

#include <array>
#include <map>

namespace holefill::testing {

Mesh surface_of(const CellSolid& solid) {
  const int nx = static_cast<int>(solid.xs.size()) - 1, ny = static_cast<int>(solid.ys.size()) - 1,
            nz = static_cast<int>(solid.zs.size()) - 1;
  auto inside = [&](int i, int j, int k) {
    return i >= 0 && j >= 0 && k >= 0 && i < nx && j < ny && k < nz && solid.filled(i, j, k);
  };
  Mesh mesh;
  std::map<std::array<int, 3>, VertexHandle> lattice;
  auto vertex = [&](std::array<int, 3> at) {
    auto [it, added] = lattice.emplace(at, VertexHandle());
    if (added)
      it->second = mesh.add_vertex(Point(solid.xs[at[0]], solid.ys[at[1]], solid.zs[at[2]]));
    return it->second;
  };
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      for (int k = 0; k < nz; ++k) {
        if (!inside(i, j, k)) continue;
        for (int axis = 0; axis < 3; ++axis) {
          for (const int side : {0, 1}) {
            std::array<int, 3> next{i, j, k};
            next[axis] += side ? 1 : -1;
            if (inside(next[0], next[1], next[2])) continue;
            // The square's corners, counter-clockwise seen from outside.
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            std::array<int, 3> base{i, j, k};
            base[axis] += side;
            std::array<std::array<int, 3>, 4> c{base, base, base, base};
            c[1][u] += 1;
            c[2][u] += 1;
            c[2][v] += 1;
            c[3][v] += 1;
            std::array<VertexHandle, 4> q;
            for (int n = 0; n < 4; ++n) q[n] = vertex(c[n]);
            if (side == 0) std::swap(q[1], q[3]);
            mesh.add_face(q[0], q[1], q[2]);
            mesh.add_face(q[0], q[2], q[3]);
          }
        }
      }
    }
  }
  return mesh;
}

std::vector<double> grid_lines(const std::vector<std::pair<double, int>>& steps) {
  std::vector<double> lines{0.0};
  for (const auto& [step, count] : steps) {
    for (int n = 0; n < count; ++n) lines.push_back(lines.back() + step);
  }
  return lines;
}

}  // namespace holefill::testing
