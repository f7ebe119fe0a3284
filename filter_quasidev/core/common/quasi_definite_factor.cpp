#include "common/quasi_definite_factor.h"

#include "common/with_cholmod.h"
#ifdef QD_WITH_CHOLMOD
#include "common/quasi_definite_ldlt.h"
#endif

namespace qd::common {
namespace {

#ifdef QD_WITH_CHOLMOD
struct SupernodalBackend : SparseFactor::Backend {
  std::shared_ptr<SharedAnalysis> shared;  // never null
  std::unique_ptr<QuasiDefiniteLdlt> ldlt;
  explicit SupernodalBackend(std::shared_ptr<SharedAnalysis> s) : shared(std::move(s)) {}
  bool analyse_and_factorize(const Eigen::SparseMatrix<double>& lower, bool analyse) override {
    if (analyse) {
      const std::lock_guard<std::mutex> lock(shared->mutex);
      if (!shared->supernodal) shared->supernodal = QuasiDefiniteLdlt::analyse(lower);
      ldlt = std::make_unique<QuasiDefiniteLdlt>(shared->supernodal);
      flops = shared->supernodal->flops;
      entries = shared->supernodal->entries;
    }
    return ldlt->factorize(lower);
  }
  Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const override {
    Eigen::MatrixXd x(b.rows(), b.cols());
    for (Eigen::Index c = 0; c < b.cols(); ++c) x.col(c) = ldlt->solve(b.col(c));
    return x;
  }
};
#endif

}  // namespace

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
  return std::make_unique<SupernodalBackend>(shared_ ? shared_
                                                     : std::make_shared<SharedAnalysis>());
#else
  throw_no_cholmod();
#endif
}

}  // namespace qd::common
