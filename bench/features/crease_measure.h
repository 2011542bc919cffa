// How a fill of a hole cut across sharp features compares with the surface that was cut away
// (README.md): how much of that surface it covers, how far the true crease inside the hole lies
// from it and how sharp the fill is there, whether it invents a crease, and whether it is clean.
#pragma once

#include <cstddef>

#include "cut_holes.h"
#include "holefill/mesh.h"
#include "measure.h"

namespace holefill::features {

// Edges whose faces meet at more than this (degrees) are the truth's creases.
constexpr double kSharpDegrees = 30.0;

struct FeatureQuality {
  quality::Quality patch;  // the quality benchmark's measures (fill -> truth, angles, dihedrals)
  // Cover: points sampled evenly over the cut-away faces, each one's distance to the nearest
  // point of the fill, / bbox diagonal: area-weighted mean and maximum.
  double cover_mean = 0.0;
  double cover_max = 0.0;
  // The truth's crease edges inside the hole (both faces cut away), sampled: their distance to
  // the fill (/ diagonal), and the fill's sharpest dihedral angle (degrees) among its own edges
  // (not those on the hole's boundary) within half a mean edge length of the fill's point
  // nearest each sample, averaged; `truth_dihedral` the truth's own angle there. NaN with no
  // crease in the hole.
  std::size_t crease_samples = 0;
  double crease_mean = 0.0;
  double crease_max = 0.0;
  double crease_dihedral = 0.0;
  double truth_dihedral = 0.0;
  // Clean: every edge has two faces used in opposite directions and every vertex one fan (no
  // hole left), and no patch triangle intersects another triangle (exact test).
  bool manifold = false;
  bool closed = false;
  std::size_t intersections = 0;
};

// Measures the fill of `hole`, one hole cut out of `closed`: `patch` is its patch in `filled`.
// `check_intersections` runs the exact brute-force test (skipped for the truth itself).
FeatureQuality measure_feature_fill(const Mesh& closed, const quality::Truth& truth,
                                    const quality::CutHole& hole, const Mesh& filled,
                                    const quality::FilledHole& patch, bool check_intersections);

}  // namespace holefill::features
