// LDLᵀ factorisation of a symmetric quasi-definite matrix K = [[H, Cᵀ], [C, −D]] (H and D
// positive definite), such as the deformation system with angle-defect rows
// (deformation_system.h). LLᵀ cannot factorise K. SolverKind::Auto and Cholmod take the
// supernodal LDLᵀ on CHOLMOD's analysis (quasi_definite_ldlt.h); EigenLDLT, and Auto in a build
// without CHOLMOD, Eigen's SimplicialLDLT. EigenLLT is substituted by SimplicialLDLT, and the
// factor says so (substituted()). Factors of one pattern may share the supernodal analysis.
#pragma once

#include <memory>

#include "common/sparse_factor.h"
#include "common/supernodal_backend.h"

namespace qd::common {

class QuasiDefiniteFactor : public SparseFactor {
 public:
  // shared: where the factors of this matrix's pattern keep its analysis (null: none shared).
  explicit QuasiDefiniteFactor(SolverKind kind, std::shared_ptr<SharedAnalysis> shared = nullptr)
      : SparseFactor(kind), shared_(std::move(shared)) {}

 private:
  Choice choose(long unknowns) const override;
  std::unique_ptr<Backend> make(FactorBackend kind) const override;
  const char* failure() const override { return "has a vanishing pivot"; }

  [[maybe_unused]] std::shared_ptr<SharedAnalysis> shared_;  // read by the supernodal back end
};

}  // namespace qd::common
