#include "comparison.h"

namespace holefill::viewer {
namespace {

ComparisonSide fill_side(const Mesh& mesh, const Hole& hole, FillOptions options,
                         WeightKind weight) {
  ComparisonSide side;
  side.weight = weight;
  side.mesh = mesh;
  options.triangulate.weight = weight;
  side.fill = fill_hole(side.mesh, hole, options);
  return side;
}

}  // namespace

Comparison compare_weights(const Mesh& mesh, const Hole& hole, const FillOptions& options,
                           bool triangulation_only) {
  FillOptions stages = options;
  stages.last_stage = triangulation_only ? Stage::Triangulated : Stage::Smoothed;
  Comparison comparison;
  comparison.hole_id = hole.id;
  comparison.triangulation_only = triangulation_only;
  comparison.left = fill_side(mesh, hole, stages, WeightKind::Liepa);
  comparison.right = fill_side(mesh, hole, stages, WeightKind::MaxMin);
  return comparison;
}

}  // namespace holefill::viewer
