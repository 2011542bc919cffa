// Fairing: an alternative to the paper's umbrella smoothing that continues the surrounding
// curvature instead of flattening the patch toward a membrane (Liepa 2003, Sec. 4).
// Solves Delta^k x = 0 (k = 2: bi-Laplacian / thin plate, k = 3: tri-Laplacian) for the
// positions of the patch's own vertices, with the boundary and k-1 rings of surrounding
// vertices held fixed, using cotangent (or uniform) weights and Eigen's sparse solvers.
//
// The operator is Delta = M^-1 K: K the stiffness matrix with cotangent weights (each cotangent
// clamped to that of 1 degree, so slivers stay finite; negative edge weights kept, so a flat
// patch stays exactly where it is) or weight 1 per edge; M the mixed Voronoi area of Meyer et
// al. 2003 (or the valence, with uniform weights, so that Delta is Liepa's umbrella operator).
// This is the discretisation CGAL's fair() uses by default, and gives the same positions on the
// same patch. The system solved is the symmetric form K (M^-1 K)^(k-1) x = 0 on the patch's rows,
// positive definite whenever every patch vertex is tied to the fixed ones, so a sparse Cholesky
// factorisation (LDLT) solves it.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

#include "holefill/mesh.h"
#include "holefill/patch.h"
#include "holefill/progress.h"

namespace holefill {

struct FairOptions {
  int order = 2;                  // 2: bi-Laplacian (C1), 3: tri-Laplacian (C2)
  bool cotangent_weights = true;  // false: uniform (umbrella) weights
  bool operator==(const FairOptions&) const = default;
};

struct FairResult {
  bool solved = false;  // false: positions unchanged, `problem` says why
  std::string problem;
  std::size_t unknowns = 0;        // patch vertices solved for
  std::size_t fixed_vertices = 0;  // boundary and surrounding rings held as boundary condition
  double relative_residual = 0.0;  // |A x - b| / |b| of the solved system
};

// Moves only patch.new_vertices. Leaves the mesh unchanged when the system cannot be solved
// (order outside 1..3, non-finite or degenerate geometry, a singular or ill-conditioned system).
// Once `progress` is cancelled it stops between the steps of the solve (building the operator,
// its powers, the factorisation, the solve) and inside the factorisation (phase::kFactorising,
// between the rows of its factor), the mesh unchanged and `problem` "cancelled".
FairResult fair_patch(Mesh& mesh, const Patch& patch, const FairOptions& options = {},
                      const Progress* progress = nullptr);

// fair_patch on the surface made of the faces `surface` accepts (the patch's own among them):
// the rings held fixed grow only across edges of those faces, and the operator sees only them,
// as if the mesh ended there. For a patch that must not feel the surface beyond a sharp edge
// (a region between continued creases, features.h).
// Stops on a cancel as fair_patch does.
FairResult fair_patch_within(Mesh& mesh, const Patch& patch, const FairOptions& options,
                             const std::function<bool(FaceHandle)>& surface,
                             const Progress* progress = nullptr);

}  // namespace holefill
