// The comparison view's data: one hole filled separately on two copies of a mesh, each side with
// its own statistics. Two comparisons: the triangulation weights (liepa left, the paper's maxmin
// right) and the smoothing (the paper's umbrella operator left, fairing right). No GL.
#pragma once

#include <string>
#include <vector>

#include "holefill/fill.h"

namespace holefill::viewer {

// The order of the panel's list.
enum class CompareMode { Weights, Smoothing, Features };

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

// Fills the region `loops` bound (the hole first, then the loops filled with it: its islands, a
// hole to bridge to; fill_joined_holes) on two copies of `mesh` with `options` but for what
// `mode` compares. Weights: with triangulation_only, both stop after the triangulation stage.
// Smoothing: both run every stage (the smoothing is what differs), with options.smooth's
// fairing settings on the right. Features: every stage, without sharp features on the left and
// with options.features (its default threshold when off) on the right. `loops` is not empty.
// Both fill on `threads` threads (FillOptions::threads; the sides' options keep options').
Comparison make_comparison(const Mesh& mesh, const std::vector<const Hole*>& loops,
                           const FillOptions& options, CompareMode mode, bool triangulation_only,
                           unsigned threads = 0);

}  // namespace holefill::viewer
