// Fairing: an alternative to the paper's umbrella smoothing that continues the surrounding
// curvature instead of flattening the patch toward a membrane (Liepa 2003, Sec. 4).
// Solves Delta^k x = 0 (k = 2: bi-Laplacian / thin plate, k = 3: tri-Laplacian) for the
// positions of the patch's own vertices, with the boundary and k-1 rings of surrounding
// vertices held fixed, using cotangent (or uniform) weights and Eigen's sparse solvers.
#pragma once

#include <string>

#include "holefill/mesh.h"
#include "holefill/patch.h"

namespace holefill {

struct FairOptions {
  int order = 2;                  // 2: bi-Laplacian (C1), 3: tri-Laplacian (C2)
  bool cotangent_weights = true;  // false: uniform (umbrella) weights
};

struct FairResult {
  bool solved = false;  // false: positions unchanged, `problem` says why
  std::string problem;
};

// Moves only patch.new_vertices. Leaves the mesh unchanged when the system cannot be solved.
FairResult fair_patch(Mesh& mesh, const Patch& patch, const FairOptions& options = {});

}  // namespace holefill
