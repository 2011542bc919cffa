// The comparison view's data: one hole filled separately on two copies of a mesh, each side with
// its own statistics. Two comparisons: the triangulation weights (liepa left, the paper's maxmin
// right) and the smoothing (the paper's umbrella operator left, fairing right). No GL.
#pragma once

#include <string>

#include "holefill/fill.h"

namespace holefill::viewer {

enum class CompareMode { Weights, Smoothing };

struct ComparisonSide {
  std::string label;    // what differs on this side: "liepa", "maxmin", "umbrella", "fair"
  FillOptions options;  // what made it (options.last_stage: how far)
  Mesh mesh;
  HoleFill fill;
};

struct Comparison {
  int hole_id = -1;
  CompareMode mode = CompareMode::Weights;
  bool triangulation_only = false;
  ComparisonSide left;   // liepa, or umbrella
  ComparisonSide right;  // maxmin, or fair
};

// Fills `hole` of two copies of `mesh` with `options` but for what `mode` compares. Weights: with
// triangulation_only, both stop after the triangulation stage. Smoothing: both run every stage
// (the smoothing is what differs), with options.smooth's fairing settings on the right.
Comparison make_comparison(const Mesh& mesh, const Hole& hole, const FillOptions& options,
                           CompareMode mode, bool triangulation_only);

}  // namespace holefill::viewer
