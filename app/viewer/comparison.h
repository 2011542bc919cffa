// The comparison view's data: one hole filled separately on two copies of a mesh, with liepa's
// weight (left) and the paper's maxmin weight (right), each with its own statistics. No GL.
#pragma once

#include <map>

#include "holefill/fill.h"

namespace holefill::viewer {

struct ComparisonSide {
  WeightKind weight = WeightKind::MaxMin;
  Mesh mesh;
  HoleFill fill;
};

struct Comparison {
  int hole_id = -1;
  bool triangulation_only = false;
  ComparisonSide left;   // liepa
  ComparisonSide right;  // maxmin
};

// Fills `hole` of copies of `mesh` with each weight and otherwise the same `options`; with
// triangulation_only, stops after the triangulation stage.
Comparison compare_weights(const Mesh& mesh, const Hole& hole, const FillOptions& options,
                           bool triangulation_only);

}  // namespace holefill::viewer
