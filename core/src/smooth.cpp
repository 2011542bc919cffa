#include "holefill/smooth.h"

#include <vector>

namespace holefill {
namespace {

Point umbrella(const Mesh& mesh, VertexHandle v) {
  Point sum(0.0, 0.0, 0.0);
  int count = 0;
  for (const auto q : mesh.vv_range(v)) {
    sum += mesh.point(q);
    ++count;
  }
  return count ? sum / count - mesh.point(v) : Point(0.0, 0.0, 0.0);
}

}  // namespace

void smooth_patch(Mesh& mesh, Patch& patch, const SmoothOptions& options) {
  std::vector<Point> moved(patch.new_vertices.size());
  for (int it = 0; it < options.iterations; ++it) {
    for (std::size_t i = 0; i < patch.new_vertices.size(); ++i) {
      const VertexHandle v = patch.new_vertices[i];
      moved[i] = mesh.point(v) + options.step * umbrella(mesh, v);
    }
    for (std::size_t i = 0; i < patch.new_vertices.size(); ++i) {
      mesh.set_point(patch.new_vertices[i], moved[i]);
    }
  }
  patch.stage = Stage::Smoothed;
}

double umbrella_energy(const Mesh& mesh, const Patch& patch) {
  double energy = 0.0;
  for (const auto v : patch.new_vertices) energy += umbrella(mesh, v).sqrnorm();
  return energy;
}

}  // namespace holefill
