// Sparse LDLᵀ of a symmetric quasi-definite matrix K = [[H, Cᵀ], [C, −D]] (H and D positive
// definite): the augmented form of a least-squares system whose rows C would otherwise add CᵀC
// to H. Every symmetric permutation of such a K has an LDLᵀ factorisation without pivoting
// (Vanderbei, SIAM J. Optim. 5, 1995), so the whole matrix can be ordered for fill alone.
//
// CHOLMOD's supernodal factorisation is LLᵀ only, so this class takes CHOLMOD's symbolic
// analysis (postorder, relaxed supernodes) and does the numeric LDLᵀ itself, supernode by
// supernode with dense BLAS kernels, and the solves: kept apart from the normal matrix, the
// angle-defect rows make a factor about three times cheaper than their CᵀC (docs/solvers.md).
// QuasiDefiniteFactor (quasi_definite_factor.h) is how the engine uses it.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

namespace qd::common {

class QuasiDefiniteLdlt {
 public:
  static constexpr int kUnblocked = 32;       // dense diagonal blocks up to this size: plain loops
  static constexpr int kUpdateColumns = 256;  // widest block of an update computed at once

  // Analyses the pattern of `lower`, the lower triangle of K (column major, sorted), already
  // in a fill-reducing order (CHOLMOD only postorders it).
  explicit QuasiDefiniteLdlt(const Eigen::SparseMatrix<double>& lower);

  // Factorises K with the values of `lower` (the pattern given at construction); false when a
  // pivot vanishes (K is not quasi-definite).
  bool factorize(const Eigen::SparseMatrix<double>& lower);
  // Solves K x = b with the current factor.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  // Columns of the widest supernode (the widest dense diagonal block).
  int widest_supernode() const;

 private:
  struct Panel {  // supernode s: its columns, rows (own columns first) and dense values
    int columns, height;
    const int* row;
    const double* X;
  };
  Panel panel(int s) const;
  void place_entries(const Eigen::SparseMatrix<double>& lower);
  bool factorize_supernode(int s, std::vector<double>& work, std::vector<int>& map);
  void update_ancestors(int s, const double* W, std::vector<double>& work, std::vector<int>& map);

  int n_ = 0;
  std::vector<int> perm_;          // row k of the factor is row perm_[k] of K
  std::vector<int> super_;         // supernode s holds columns super_[s] .. super_[s+1]
  std::vector<int> row_start_;     // its row indices rows_[row_start_[s] .. row_start_[s+1])
  std::vector<int> rows_;          //   (its own columns first, then the rows below)
  std::vector<long> value_start_;  // its dense column-major panel at values_[value_start_[s]]
  std::vector<int> owner_;         // supernode of each column
  std::vector<long> slot_;         // place in values_ of each stored entry of `lower`
  std::vector<double> values_;     // unit-lower L (diagonal entries hold D)
};

}  // namespace qd::common
