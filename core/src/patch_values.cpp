#include "patch_values.h"

#include <cmath>

namespace holefill::detail {

void interpolate_harmonically(Mesh& mesh, const Patch& patch,
                              const std::vector<OpenMesh::VPropHandleT<double>>& scalars) {
  if (scalars.empty() || patch.new_vertices.empty()) return;
  for (const auto property : scalars) {
    double sum = 0.0;
    for (const auto v : patch.boundary) sum += mesh.property(property, v);
    const double mean =
        patch.boundary.empty() ? 0.0 : sum / static_cast<double>(patch.boundary.size());
    for (const auto v : patch.new_vertices) mesh.property(property, v) = mean;
  }
  constexpr int kMaxSweeps = 500;
  constexpr double kTolerance = 1e-9;
  for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
    double change = 0.0;
    for (const auto v : patch.new_vertices) {
      for (const auto property : scalars) {
        double sum = 0.0;
        int count = 0;
        for (const auto neighbour : mesh.vv_range(v)) {
          sum += mesh.property(property, neighbour);
          ++count;
        }
        if (count == 0) continue;
        double& value = mesh.property(property, v);
        const double updated = sum / count;
        change = std::max(change, std::abs(updated - value) / (1.0 + std::abs(updated)));
        value = updated;
      }
    }
    if (change < kTolerance) break;
  }
}

}  // namespace holefill::detail
