// Sparse LDLᵀ of a symmetric quasi-definite matrix K = [[H, Cᵀ], [C, −D]] (H and D positive
// definite): the augmented form of a least-squares system whose rows C would otherwise add CᵀC
// to H. Every symmetric permutation of such a K has an LDLᵀ factorisation without pivoting
// (Vanderbei, SIAM J. Optim. 5, 1995), so the whole matrix can be ordered for fill alone.
//
// CHOLMOD's supernodal factorisation is LLᵀ only, so this class takes CHOLMOD's symbolic
// analysis (postorder, relaxed supernodes) and does the numeric LDLᵀ itself, supernode by
// supernode with dense BLAS kernels, and the solves: kept apart from the normal matrix, the
// angle-defect rows make a factor about three times cheaper than their CᵀC (docs/solvers.md).
// The symbolic analysis depends on K's pattern alone, so factors of one pattern may share it.
// QuasiDefiniteFactor (quasi_definite_factor.h) is how the engine uses it.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "common/huge_page_allocator.h"

namespace qd::common {

// The symbolic analysis of a pattern: supernodes, their rows and where each entry goes.
struct SupernodalAnalysis {
  int n = 0;
  std::vector<int> perm;          // row k of the factor is row perm[k] of K
  std::vector<int> super;         // supernode s holds columns super[s] .. super[s+1]
  std::vector<int> row_start;     // its row indices rows[row_start[s] .. row_start[s+1])
  std::vector<int> rows;          //   (its own columns first, then the rows below)
  std::vector<long> value_start;  // its dense column-major panel at values[value_start[s]]
  std::vector<int> owner;         // supernode of each column
  std::vector<long> slot;         // place in the values of each stored entry of `lower` (or −1)
  size_t values = 0;              // the factor's values
  double flops = 0;               // CHOLMOD's count (of an LLᵀ of the same pattern)
  double entries = 0;             // L's nonzeros (the values hold explicit zeros too)
};

class QuasiDefiniteLdlt {
 public:
  static constexpr int kUnblocked = 32;       // dense diagonal blocks up to this size: plain loops
  static constexpr int kUpdateColumns = 256;  // widest block of an update computed at once

  // Analyses the pattern of `lower`, the lower triangle of K (column major, sorted; entries
  // above the diagonal are ignored), already in a fill-reducing order (CHOLMOD only
  // postorders it).
  static std::shared_ptr<const SupernodalAnalysis> analyse(
      const Eigen::SparseMatrix<double>& lower);
  explicit QuasiDefiniteLdlt(std::shared_ptr<const SupernodalAnalysis> analysis);
  explicit QuasiDefiniteLdlt(const Eigen::SparseMatrix<double>& lower)
      : QuasiDefiniteLdlt(analyse(lower)) {}

  // Factorises K with the values of `lower` (the pattern given at construction); false when a
  // pivot vanishes (K is not quasi-definite).
  bool factorize(const Eigen::SparseMatrix<double>& lower);
  // Every pivot of the current factor is positive: K is positive definite.
  bool pivots_positive() const;
  // Solves K x = b with the current factor, for every column of b at once.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const;  // every column of b at once
  // Columns of the widest supernode (the widest dense diagonal block).
  int widest_supernode() const;

 private:
  struct Panel {  // supernode s: its columns, rows (own columns first) and dense values
    int columns, height;
    const int* row;
    const double* X;
  };
  Panel panel(int s) const;
  bool factorize_supernode(int s, std::vector<double>& work, std::vector<int>& map);
  void update_ancestors(int s, const double* W, std::vector<double>& work, std::vector<int>& map);

  std::shared_ptr<const SupernodalAnalysis> a_;
  std::vector<double, HugePageAllocator<double>> values_;  // unit-lower L (diagonal entries hold D)
};

}  // namespace qd::common
