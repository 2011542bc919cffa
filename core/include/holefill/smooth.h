// Step 3 of the paper: umbrella (uniform Laplacian) smoothing of a patch (Sec. II, Step 3).
//   U(P) = (1/n) sum Qi - P,   P <- P + lambda U(P),
// applied simultaneously to the patch's own vertices; boundary and original vertices never move.
#pragma once

#include "holefill/mesh.h"
#include "holefill/patch.h"

namespace holefill {

struct SmoothOptions {
  int iterations = 10;
  double step = 0.5;  // lambda; the paper gives none
};

void smooth_patch(Mesh& mesh, Patch& patch, const SmoothOptions& options = {});

// Sum over the patch's own vertices of |U(P)|^2: what umbrella smoothing drives down.
double umbrella_energy(const Mesh& mesh, const Patch& patch);

}  // namespace holefill
