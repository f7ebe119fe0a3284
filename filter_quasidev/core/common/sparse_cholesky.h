// Sparse Cholesky factorisation of the SPD normal matrix (paper §5.4, Eq. 17). The matrix
// arrives already in a fill-reducing order (vertex_order.h), so no back end reorders it; the
// symbolic analysis is done on the first factorisation and reused, since a group's sparsity
// pattern never changes. Back ends: CHOLMOD supernodal LLᵀ (SuiteSparse), Eigen's SimplicialLLT
// and SimplicialLDLT. SolverKind::Auto takes SimplicialLDLT below kCholmodFromUnknowns unknowns
// and CHOLMOD from there on (the crossover measured by bench/qd_bench: docs/performance.md), or
// SimplicialLDLT always in a build without CHOLMOD. Measured with bench/qd_bench --grid N --
// --max-iter 3 --method direct, three factorisations (CHOLMOD / SimplicialLDLT, ms): 675
// unknowns 3.2 / 1.2, 1,386 3.9 / 4.1, 2,883 9.8 / 17.
//
// Groups with angle-defect rows factorise a quasi-definite K = [[M, Cᵀ], [C, −I]] instead
// (deformation_system.h), which LLᵀ cannot: SolverKind::Auto and Cholmod take our supernodal
// LDLᵀ on CHOLMOD's analysis (quasi_definite_ldlt.h) at every size in a build with CHOLMOD, the
// others (and a build without CHOLMOD) Eigen's SimplicialLDLT.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>

namespace qd {

enum class SolverKind { Auto, Cholmod, EigenLLT, EigenLDLT };  // back end (§5.4)

constexpr long kCholmodFromUnknowns = 1500;

enum class Definiteness { Positive, Quasi };  // of the matrix to factorise

class SparseCholesky {
 public:
  // many_solves: the factor will serve many solves, possibly two at once in two threads. CHOLMOD's
  // supernodal factor is then converted to simplicial form after each factorisation: its solve
  // makes no BLAS calls, whose buffer locks serialised the frame preconditioner's two concurrent
  // solves (1M triangles, 5 iterations: solve stage 4.7 s supernodal, 3.4 s simplicial).
  explicit SparseCholesky(SolverKind kind, bool many_solves = false,
                          Definiteness definiteness = Definiteness::Positive);
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  // Factorises M (lower triangle used); throws qd::Error if it cannot (M not positive definite,
  // or a vanishing pivot of a quasi-definite one).
  void factorize(const Eigen::SparseMatrix<double>& M);
  // Solves M x = b by forward and back substitution with the current factor; b may have
  // several columns (right-hand sides), which share one pass over the factor.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const;
  int factorizations() const { return factorizations_; }

  struct Backend;

 private:
  SolverKind kind_;
  bool many_solves_;
  Definiteness definiteness_;
  std::unique_ptr<Backend> backend_;  // chosen on the first factorisation
  int factorizations_ = 0;
};

}  // namespace qd
