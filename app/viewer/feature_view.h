// The sharp features the viewer shows near the selected hole (holefill/features.h): found on the
// mesh as loaded, where every hole is still open, so that they show before and after the fill.
// Computed once per hole and threshold, on the UI thread (a trace of a few edges per boundary
// vertex). No GL.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "holefill/features.h"
#include "holefill/holes.h"
#include "scene_arrays.h"

namespace holefill::viewer {

class FeatureView {
 public:
  // The features of `hole` on `mesh` under `options`; nothing when `hole` is null. `mesh_version`
  // names the mesh: a new one (another file) is looked at anew.
  const HoleFeatures& of(const Mesh& mesh, std::uint64_t mesh_version, const Hole* hole,
                         const FeatureOptions& options);
  // Changes whenever of() gives other features; 0 before the first call.
  std::uint64_t version() const { return version_; }

 private:
  std::uint64_t mesh_version_ = 0;
  int hole_id_ = -1;
  FeatureOptions options_;
  HoleFeatures features_;
  std::uint64_t version_ = 0;
};

// One line for the panel: how many feature lines enter the hole and what became of them ("2
// sharp feature lines enter the hole: continued as a crease"); empty when none does.
std::string feature_summary(const HoleFeatures& features);

// The lines to draw: the feature lines traced outward from the hole (`continued` false), or
// their continuations across it, entry to entry or entry to corner (`continued` true). Each
// segment carries hole id -1 (no outline colour applies to it).
std::vector<BoundarySegment> feature_segments(const HoleFeatures& features, bool continued);

}  // namespace holefill::viewer
