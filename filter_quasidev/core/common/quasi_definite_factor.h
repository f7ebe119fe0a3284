// LDLᵀ factorisation of a symmetric quasi-definite matrix K = [[H, Cᵀ], [C, −D]] (H and D
// positive definite), such as the deformation system with angle-defect rows
// (deformation_system.h). LLᵀ cannot factorise K. SolverKind::Auto and Cholmod take the
// supernodal LDLᵀ on CHOLMOD's analysis (quasi_definite_ldlt.h); EigenLDLT, and Auto in a build
// without CHOLMOD, Eigen's SimplicialLDLT. EigenLLT is substituted by SimplicialLDLT, and the
// factor says so (substituted()).
#pragma once

#include "common/sparse_factor.h"

namespace qd::common {

class QuasiDefiniteFactor : public SparseFactor {
 public:
  explicit QuasiDefiniteFactor(SolverKind kind) : SparseFactor(kind) {}

 private:
  Choice choose(long unknowns) const override;
  std::unique_ptr<Backend> make(FactorBackend kind) const override;
  const char* failure() const override { return "has a vanishing pivot"; }
};

}  // namespace qd::common
