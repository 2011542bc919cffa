#include "cancellable_ldlt.h"

#include <vector>

namespace holefill::detail {

// Row k of L solves L(0:k-1, 0:k-1) D l = A(0:k-1, k), a sparse triangular solve whose nonzeros
// are the elimination-tree paths from the nonzeros of column k of A up to k (Davis, "Direct
// Methods for Sparse Linear Systems", 2006, ch. 4). Each path is walked until a node this row has
// already reached, and the paths are stacked so that a node is solved after every node below it.
// The columns of L are filled in the space the analysis counted for them.
bool CancellableLdlt::factorize_unless_cancelled(const Eigen::SparseMatrix<double>& matrix,
                                                 const Progress* progress) {
  enter_phase(progress, phase::kFactorising);
  m_factorizationIsOk = false;
  const auto n = static_cast<StorageIndex>(matrix.cols());
  // The lower triangle read as symmetric, permuted by the analysis's ordering, as the upper
  // triangle factorize() works on.
  CholMatrixType permuted(n, n);
  permuted.selfadjointView<Eigen::Upper>() = matrix.selfadjointView<Eigen::Lower>().twistedBy(m_P);
  const StorageIndex* column_start = m_matrix.outerIndexPtr();
  StorageIndex* rows = m_matrix.innerIndexPtr();
  double* values = m_matrix.valuePtr();
  std::vector<double> dense(static_cast<std::size_t>(n), 0.0);  // row k of L D, being solved
  std::vector<StorageIndex> reach(static_cast<std::size_t>(n));
  std::vector<StorageIndex> reached_by_row(static_cast<std::size_t>(n));
  m_diag.resize(n);
  m_info = Eigen::Success;
  for (StorageIndex k = 0; k < n; ++k) {
    if (is_cancelled(progress)) return false;
    StorageIndex first = n;  // reach[first, n) are the row's nonzeros, in solving order
    dense[k] = 0.0;
    reached_by_row[k] = k;
    m_nonZerosPerCol[k] = 0;
    for (CholMatrixType::InnerIterator entry(permuted, k); entry; ++entry) {
      StorageIndex node = static_cast<StorageIndex>(entry.index());
      if (node > k) continue;
      dense[node] += entry.value();
      StorageIndex path = 0;
      for (; reached_by_row[node] != k; node = m_parent[node]) {
        reach[path++] = node;
        reached_by_row[node] = k;
      }
      while (path > 0) reach[--first] = reach[--path];
    }
    double pivot = dense[k] * m_shiftScale + m_shiftOffset;
    dense[k] = 0.0;
    for (; first < n; ++first) {
      const StorageIndex i = reach[first];
      const double solved = dense[i];
      dense[i] = 0.0;
      const double l_ki = solved / m_diag[i];
      const StorageIndex end = column_start[i] + m_nonZerosPerCol[i];
      for (StorageIndex p = column_start[i]; p < end; ++p) dense[rows[p]] -= values[p] * solved;
      pivot -= l_ki * solved;
      rows[end] = k;
      values[end] = l_ki;
      ++m_nonZerosPerCol[i];
    }
    m_diag[k] = pivot;
    if (pivot == 0.0) {
      m_info = Eigen::NumericalIssue;
      break;
    }
  }
  m_factorizationIsOk = true;
  return true;
}

}  // namespace holefill::detail
