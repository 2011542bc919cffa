// Eigen's sparse LDL^T whose numeric factorisation can be stopped (fair.cpp): Eigen's factorize()
// is one call that took 16 of the 28 s fairing a 208K-vertex patch, with no way to stop it.
#pragma once

#include <Eigen/SparseCholesky>

#include "holefill/progress.h"

namespace holefill::detail {

class CancellableLdlt : public Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> {
 public:
  // factorize(matrix), after analyzePattern(matrix): the same factor bit for bit (the same
  // up-looking elimination, row by row of L in the analysis's order, each sum taken in Eigen's
  // order), so that solve() and info() answer as after factorize(). It enters
  // phase::kFactorising and looks at `progress` before each row: once it is cancelled, false,
  // and the solver is left unusable until factorised again.
  bool factorize_unless_cancelled(const Eigen::SparseMatrix<double>& matrix,
                                  const Progress* progress);
};

}  // namespace holefill::detail
