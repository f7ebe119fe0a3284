#include "common/quasi_definite_factor.h"

#include "common/with_cholmod.h"

namespace qd::common {

SparseFactor::Choice QuasiDefiniteFactor::choose(long) const {
  switch (kind_) {
    case SolverKind::Auto:
      return {kHaveCholmod ? FactorBackend::SupernodalLdlt : FactorBackend::EigenLdlt, false};
    case SolverKind::Cholmod:
      return {FactorBackend::SupernodalLdlt, false};
    case SolverKind::EigenLLT:
      return {FactorBackend::EigenLdlt, true};  // LLᵀ cannot factorise K
    case SolverKind::EigenLDLT:
      break;
  }
  return {FactorBackend::EigenLdlt, false};
}

std::unique_ptr<SparseFactor::Backend> QuasiDefiniteFactor::make(FactorBackend kind) const {
  if (kind == FactorBackend::EigenLdlt) return std::make_unique<EigenLdlt>();
#ifdef QD_WITH_CHOLMOD
  return supernodal_backend(shared_ ? shared_ : std::make_shared<SharedAnalysis>(), false);
#else
  throw_no_cholmod();
#endif
}

}  // namespace qd::common
