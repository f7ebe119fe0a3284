// Sparse Cholesky factorisation of a symmetric positive-definite matrix, such as the normal
// matrix M of Eq. (17) (paper §5.4) or the flattening's Laplacians. Back ends: CHOLMOD's
// supernodal LLᵀ (SuiteSparse), the supernodal LDLᵀ on CHOLMOD's analysis
// (supernodal_backend.h), Eigen's SimplicialLLT and SimplicialLDLT. SolverKind::Auto takes
// SimplicialLDLT below kCholmodFromUnknowns unknowns; from there on the supernodal LDLᵀ, or
// CHOLMOD's LLᵀ for a factor that serves many solves one after another; SimplicialLDLT always
// in a build without CHOLMOD (the measurements: docs/solvers.md). SolverKind::Cholmod takes
// CHOLMOD's LLᵀ.
#pragma once

#include "common/sparse_factor.h"

namespace qd::common {

// How a factor's solves come: a few per factorisation (M's direct solves), from two threads at
// once (the frame preconditioner's), or many one after another (ARAP's global steps).
enum class Solves { Few, AtOnce, Many };

class PositiveDefiniteFactor : public SparseFactor {
 public:
  // A CHOLMOD factor that serves solves at once or many solves is converted to simplicial form
  // after each factorisation: its solve then makes no BLAS calls, whose buffer locks serialise
  // concurrent solves, and it is the faster for many small solves.
  explicit PositiveDefiniteFactor(SolverKind kind, Solves solves = Solves::Few)
      : SparseFactor(kind), solves_(solves) {}

 private:
  Choice choose(long unknowns) const override;
  std::unique_ptr<Backend> make(FactorBackend kind) const override;
  const char* failure() const override { return "is not positive definite"; }

  Solves solves_;
};

}  // namespace qd::common
