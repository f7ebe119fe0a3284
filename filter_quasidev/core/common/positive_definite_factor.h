// Sparse Cholesky factorisation of a symmetric positive-definite matrix, such as the normal
// matrix M of Eq. (17) (paper §5.4) or the flattening's Laplacians. Back ends: CHOLMOD's
// supernodal LLᵀ (SuiteSparse), the supernodal LDLᵀ on CHOLMOD's analysis
// (supernodal_backend.h), Eigen's SimplicialLLT and SimplicialLDLT. SolverKind::Auto takes
// SimplicialLDLT below kCholmodFromUnknowns unknowns; from there on the supernodal LDLᵀ, or
// CHOLMOD's LLᵀ for a factor that serves many solves; SimplicialLDLT always in a build without
// CHOLMOD (the measurements: docs/solvers.md). SolverKind::Cholmod takes CHOLMOD's LLᵀ.
#pragma once

#include "common/sparse_factor.h"

namespace qd::common {

class PositiveDefiniteFactor : public SparseFactor {
 public:
  // many_solves: the factor will serve many solves, possibly two at once in two threads: Auto
  // takes CHOLMOD's factor, converted to simplicial form after each factorisation (its solve
  // then makes no BLAS calls, whose buffer locks serialise concurrent solves).
  explicit PositiveDefiniteFactor(SolverKind kind, bool many_solves = false)
      : SparseFactor(kind), many_solves_(many_solves) {}

 private:
  Choice choose(long unknowns) const override;
  std::unique_ptr<Backend> make(FactorBackend kind) const override;
  const char* failure() const override { return "is not positive definite"; }

  bool many_solves_;
};

}  // namespace qd::common
