#include "common/sparse_cholesky.h"

#include <Eigen/SparseCholesky>
#ifdef QD_WITH_CHOLMOD
#include <Eigen/CholmodSupport>

#include "common/quasi_definite_ldlt.h"
constexpr bool kHaveCholmod = true;
#else
constexpr bool kHaveCholmod = false;  // the build for plugins whose host ships no SuiteSparse
#endif

#include <string>

#include "common/error.h"

namespace qd {

struct SparseCholesky::Backend {
  virtual ~Backend() = default;
  virtual bool analyse_and_factorize(const Eigen::SparseMatrix<double>& M, bool analyse) = 0;
  virtual Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const = 0;
};

namespace {

// Any of Eigen's sparse Cholesky classes (its own or its CHOLMOD wrappers).
template <typename Solver>
struct EigenApiBackend : SparseCholesky::Backend {
  Solver solver;
  bool analyse_and_factorize(const Eigen::SparseMatrix<double>& M, bool analyse) override {
    if (analyse) solver.analyzePattern(M);
    solver.factorize(M);
    return solver.info() == Eigen::Success;
  }
  Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const override { return solver.solve(b); }
};

using Matrix = Eigen::SparseMatrix<double>;
using Natural = Eigen::NaturalOrdering<int>;

#ifdef QD_WITH_CHOLMOD
// Eigen's supernodal wrapper, with access to its factor.
struct Supernodal : Eigen::CholmodSupernodalLLT<Matrix, Eigen::Lower> {
  // Converts the factor to simplicial form (same values, columns stored one by one).
  bool to_simplicial() { return cholmod_change_factor(CHOLMOD_REAL, 1, 0, 1, 1, m_cholmodFactor, &cholmod()); }
};

struct CholmodBackend : EigenApiBackend<Supernodal> {
  bool simplicial_solves;
  bool converted = false;  // the factor is simplicial: the next factorisation analyses again
  explicit CholmodBackend(bool simplicial) : simplicial_solves(simplicial) {
    cholmod_common& c = solver.cholmod();
    c.nmethods = 1;  // the given (already fill-reducing) order, no AMD/METIS trials
    c.method[0].ordering = CHOLMOD_NATURAL;
    c.postorder = 1;
  }
  bool analyse_and_factorize(const Eigen::SparseMatrix<double>& M, bool analyse) override {
    bool ok = EigenApiBackend<Supernodal>::analyse_and_factorize(M, analyse || converted);
    if (ok && simplicial_solves) ok = converted = solver.to_simplicial();
    return ok;
  }
};

struct QuasiDefiniteBackend : SparseCholesky::Backend {
  std::unique_ptr<QuasiDefiniteLdlt> ldlt;
  bool analyse_and_factorize(const Eigen::SparseMatrix<double>& M, bool analyse) override {
    if (analyse) ldlt = std::make_unique<QuasiDefiniteLdlt>(M);
    return ldlt->factorize(M);
  }
  Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const override {
    Eigen::MatrixXd x(b.rows(), b.cols());
    for (Eigen::Index c = 0; c < b.cols(); ++c) x.col(c) = ldlt->solve(b.col(c));
    return x;
  }
};
#endif

std::unique_ptr<SparseCholesky::Backend> make_backend(SolverKind kind, long unknowns,
                                                      [[maybe_unused]] bool simplicial_solves,
                                                      Definiteness definiteness) {
  const bool quasi = definiteness == Definiteness::Quasi;
  if (kind == SolverKind::Auto)
    kind = (unknowns < kCholmodFromUnknowns && !quasi) || !kHaveCholmod ? SolverKind::EigenLDLT
                                                                         : SolverKind::Cholmod;
  if (quasi && kind == SolverKind::EigenLLT) kind = SolverKind::EigenLDLT;  // LLᵀ cannot factorise K
  switch (kind) {
    case SolverKind::EigenLLT:
      return std::make_unique<EigenApiBackend<Eigen::SimplicialLLT<Matrix, Eigen::Lower, Natural>>>();
    case SolverKind::EigenLDLT:
      return std::make_unique<EigenApiBackend<Eigen::SimplicialLDLT<Matrix, Eigen::Lower, Natural>>>();
    case SolverKind::Auto:
    case SolverKind::Cholmod:
      break;
  }
#ifdef QD_WITH_CHOLMOD
  if (quasi) return std::make_unique<QuasiDefiniteBackend>();
  return std::make_unique<CholmodBackend>(simplicial_solves);
#else
  throw Error("this build of the engine has no CHOLMOD: choose the eigen-llt or eigen-ldlt solver");
#endif
}

}  // namespace

SparseCholesky::SparseCholesky(SolverKind kind, bool many_solves, Definiteness definiteness)
    : kind_(kind), many_solves_(many_solves), definiteness_(definiteness) {}
SparseCholesky::~SparseCholesky() = default;

void SparseCholesky::factorize(const Eigen::SparseMatrix<double>& M) {
  if (!backend_) backend_ = make_backend(kind_, M.rows(), many_solves_, definiteness_);
  const bool ok = backend_->analyse_and_factorize(M, factorizations_ == 0);
  ++factorizations_;
  if (!ok)
    throw Error(std::string("the deformation system ") +
                (definiteness_ == Definiteness::Positive ? "is not positive definite" : "has a vanishing pivot") +
                " (degenerate faces?): remove zero-area and duplicate faces, then try again");
}

Eigen::MatrixXd SparseCholesky::solve(const Eigen::MatrixXd& b) const { return backend_->solve(b); }

}  // namespace qd
