#include "common/positive_definite_factor.h"

#include "common/with_cholmod.h"
#ifdef QD_WITH_CHOLMOD
#include <Eigen/CholmodSupport>

#include "common/supernodal_backend.h"
#endif

namespace qd::common {
namespace {

using Matrix = Eigen::SparseMatrix<double>;

// LDLᵀ factorises indefinite matrices too: a pivot D ≤ 0 says the matrix is not SPD.
struct DefiniteLdlt : SparseFactor::EigenLdlt {
  bool analyse_and_factorize(const Matrix& lower, bool analyse) override {
    return SparseFactor::EigenLdlt::analyse_and_factorize(lower, analyse) &&
           (lower.rows() == 0 || solver.vectorD().minCoeff() > 0);
  }
};

#ifdef QD_WITH_CHOLMOD

// Eigen's supernodal wrapper, with access to its factor.
struct Supernodal : Eigen::CholmodSupernodalLLT<Matrix, Eigen::Lower> {
  // Converts the factor to simplicial form (same values, columns stored one by one).
  bool to_simplicial() {
    return cholmod_change_factor(CHOLMOD_REAL, 1, 0, 1, 1, m_cholmodFactor, &cholmod());
  }
};

struct CholmodBackend : SparseFactor::EigenBackend<Supernodal> {
  bool simplicial_solves;
  bool converted = false;  // the factor is simplicial: the next factorisation analyses again
  explicit CholmodBackend(bool simplicial) : simplicial_solves(simplicial) {
    cholmod_common& c = solver.cholmod();
    c.nmethods = 1;  // the given (already fill-reducing) order, no AMD/METIS trials
    c.method[0].ordering = CHOLMOD_NATURAL;
    c.postorder = 1;
  }
  bool analyse_and_factorize(const Matrix& lower, bool analyse) override {
    const bool analysing = analyse || converted;
    bool ok = EigenBackend<Supernodal>::analyse_and_factorize(lower, analysing);
    if (analysing) flops = solver.cholmod().fl, entries = solver.cholmod().lnz;  // the analysis's
    if (ok && simplicial_solves) ok = converted = solver.to_simplicial();
    return ok;
  }
};
#endif

}  // namespace

SparseFactor::Choice PositiveDefiniteFactor::choose(long unknowns) const {
  switch (kind_) {
    case SolverKind::Auto:
      if (unknowns < kCholmodFromUnknowns || !kHaveCholmod)
        return {FactorBackend::EigenLdlt, false};
      return {solves_ == Solves::Many ? FactorBackend::CholmodLlt : FactorBackend::SupernodalLdlt,
              false};
    case SolverKind::Cholmod:
      return {FactorBackend::CholmodLlt, false};
    case SolverKind::EigenLLT:
      return {FactorBackend::EigenLlt, false};
    case SolverKind::EigenLDLT:
      break;
  }
  return {FactorBackend::EigenLdlt, false};
}

std::unique_ptr<SparseFactor::Backend> PositiveDefiniteFactor::make(FactorBackend kind) const {
  if (kind == FactorBackend::EigenLlt) return std::make_unique<EigenLlt>();
  if (kind == FactorBackend::EigenLdlt) return std::make_unique<DefiniteLdlt>();
#ifdef QD_WITH_CHOLMOD
  if (kind == FactorBackend::SupernodalLdlt)
    return supernodal_backend(std::make_shared<SharedAnalysis>(), true);
  return std::make_unique<CholmodBackend>(solves_ != Solves::Few);
#else
  throw_no_cholmod();
#endif
}

}  // namespace qd::common
