#include "common/quasi_definite_solver.h"

#include <Eigen/SparseCholesky>

#include "common/error.h"
#ifdef QD_WITH_CHOLMOD
#include "common/quasi_definite_ldlt.h"
#endif

namespace qd {

struct QuasiDefiniteSolver::Backend {
  virtual ~Backend() = default;
  virtual void factorize(const Eigen::SparseMatrix<double>& lower) = 0;
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& b) const = 0;
};

namespace {

struct EigenBackend : QuasiDefiniteSolver::Backend {
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> ldlt;
  explicit EigenBackend(const Eigen::SparseMatrix<double>& lower) { ldlt.analyzePattern(lower); }
  void factorize(const Eigen::SparseMatrix<double>& lower) override {
    ldlt.factorize(lower);
    if (ldlt.info() != Eigen::Success)
      throw Error(
          "the deformation system has a vanishing pivot (degenerate faces?): remove zero-area and "
          "duplicate faces, then try again");
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const override { return ldlt.solve(b); }
};

#ifdef QD_WITH_CHOLMOD
struct SupernodalBackend : QuasiDefiniteSolver::Backend {
  QuasiDefiniteLdlt ldlt;
  explicit SupernodalBackend(const Eigen::SparseMatrix<double>& lower) : ldlt(lower) {}
  void factorize(const Eigen::SparseMatrix<double>& lower) override { ldlt.factorize(lower); }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const override { return ldlt.solve(b); }
};
#endif

std::unique_ptr<QuasiDefiniteSolver::Backend> make_backend(SolverKind kind, const Eigen::SparseMatrix<double>& lower) {
#ifdef QD_WITH_CHOLMOD
  if (kind == SolverKind::Auto || kind == SolverKind::Cholmod)
    return std::make_unique<SupernodalBackend>(lower);
#else
  if (kind == SolverKind::Cholmod)
    throw Error("this build of the engine has no CHOLMOD: choose the eigen-llt or eigen-ldlt solver");
#endif
  return std::make_unique<EigenBackend>(lower);
}

}  // namespace

QuasiDefiniteSolver::QuasiDefiniteSolver(SolverKind kind) : kind_(kind) {}
QuasiDefiniteSolver::~QuasiDefiniteSolver() = default;

void QuasiDefiniteSolver::factorize(const Eigen::SparseMatrix<double>& lower) {
  if (!backend_) backend_ = make_backend(kind_, lower);
  backend_->factorize(lower);
  ++factorizations_;
}

Eigen::VectorXd QuasiDefiniteSolver::solve(const Eigen::VectorXd& b) const { return backend_->solve(b); }

}  // namespace qd
