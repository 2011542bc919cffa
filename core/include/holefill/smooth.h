// Step 3 of the paper: umbrella (uniform Laplacian) smoothing of a patch (Sec. II, Step 3).
//   U(P) = (1/n) sum Qi - P,   P <- P + lambda U(P),
// applied simultaneously to the patch's own vertices; boundary and original vertices never move.
#pragma once

#include "holefill/fair.h"
#include "holefill/mesh.h"
#include "holefill/patch.h"
#include "holefill/progress.h"

namespace holefill {

enum class SmoothMethod { Umbrella, Fair };

struct SmoothOptions {
  SmoothMethod method = SmoothMethod::Umbrella;  // the paper's; Fair continues the curvature
  int iterations = 10;                           // umbrella only
  double step = 0.5;                             // umbrella lambda; the paper gives none
  FairOptions fair;                              // fair only
  bool operator==(const SmoothOptions&) const = default;
};

// Moves the patch's new vertices by `options.iterations` umbrella steps of `options.step`; the
// boundary and the original mesh never move, and patch.stage is left to the pipeline (fill.h).
// Umbrella smoothing only: asking for fairing here (options.method == Fair) throws
// std::invalid_argument rather than smoothing some other way; fairing is fair_patch, which can
// fail, and the pipeline falls back to this when it does. Once `progress` is cancelled it stops
// before its next iteration, the mesh unchanged.
void smooth_patch(Mesh& mesh, const Patch& patch, const SmoothOptions& options = {},
                  const Progress* progress = nullptr);

// Sum over the patch's own vertices of |U(P)|^2: what umbrella smoothing drives down.
double umbrella_energy(const Mesh& mesh, const Patch& patch);

}  // namespace holefill
