// Sparse Cholesky factorisation of a symmetric positive-definite matrix, such as the normal
// matrix M of Eq. (17) (paper §5.4) or the flattening's Laplacians. Back ends: CHOLMOD's
// supernodal LLᵀ (SuiteSparse), Eigen's SimplicialLLT and SimplicialLDLT. SolverKind::Auto takes
// SimplicialLDLT below kCholmodFromUnknowns unknowns and CHOLMOD from there on, or
// SimplicialLDLT always in a build without CHOLMOD (the crossover: docs/solvers.md).
#pragma once

#include "common/sparse_factor.h"

namespace qd::common {

class PositiveDefiniteFactor : public SparseFactor {
 public:
  // many_solves: the factor will serve many solves, possibly two at once in two threads, so
  // CHOLMOD's supernodal factor is converted to simplicial form after each factorisation (its
  // solve then makes no BLAS calls, whose buffer locks serialise concurrent solves).
  explicit PositiveDefiniteFactor(SolverKind kind, bool many_solves = false)
      : SparseFactor(kind), many_solves_(many_solves) {}

 private:
  Choice choose(long unknowns) const override;
  std::unique_ptr<Backend> make(FactorBackend kind) const override;
  const char* failure() const override { return "is not positive definite"; }

  [[maybe_unused]] bool many_solves_;  // read by the CHOLMOD back end only
};

}  // namespace qd::common
