#include "comparison.h"

namespace holefill::viewer {
namespace {

ComparisonSide fill_side(const Mesh& mesh, const std::vector<const Hole*>& loops,
                         const FillOptions& options, std::string label, unsigned threads) {
  ComparisonSide side;
  side.label = std::move(label);
  side.options = options;
  side.mesh = mesh;
  FillOptions run = options;
  run.threads = threads;
  side.fill = fill_joined_holes(side.mesh, loops, run);
  return side;
}

}  // namespace

Comparison make_comparison(const Mesh& mesh, const std::vector<const Hole*>& loops,
                           const FillOptions& options, CompareMode mode, bool triangulation_only,
                           unsigned threads) {
  Comparison comparison;
  comparison.hole_id = loops.front()->id;
  comparison.mode = mode;
  FillOptions left = options, right = options;
  if (mode == CompareMode::Weights) {
    comparison.triangulation_only = triangulation_only;
    left.last_stage = right.last_stage = triangulation_only ? Stage::Triangulated : Stage::Smoothed;
    left.triangulate.weight = WeightKind::Liepa;
    right.triangulate.weight = WeightKind::MaxMin;
  } else if (mode == CompareMode::Smoothing) {
    left.last_stage = right.last_stage = Stage::Smoothed;
    left.smooth.method = SmoothMethod::Umbrella;
    right.smooth.method = SmoothMethod::Fair;
  } else {
    left.last_stage = right.last_stage = Stage::Smoothed;
    left.features.angle_degrees = 0.0;
    if (right.features.angle_degrees <= 0.0) right.features = FeatureOptions{};
  }
  static constexpr const char* kLabels[][2] = {
      {"liepa", "maxmin"}, {"umbrella", "fair"}, {"paper", "creases"}};
  const auto labels = kLabels[static_cast<int>(mode)];
  comparison.left = fill_side(mesh, loops, left, labels[0], threads);
  comparison.right = fill_side(mesh, loops, right, labels[1], threads);
  return comparison;
}

}  // namespace holefill::viewer
