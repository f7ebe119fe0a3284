// One interface for the engine's sparse symmetric factorisations: positive_definite_factor.h
// (LLᵀ or LDLᵀ of an SPD matrix) and quasi_definite_factor.h (LDLᵀ of [[H, Cᵀ], [C, −D]]).
// The matrix arrives already in a fill-reducing order (vertex_order.h), so no back end
// reorders it; the symbolic analysis is done on the first factorisation and reused, since the
// pattern never changes. Which back end runs is reported, and so is a substitution of the one
// asked for.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <memory>
#include <type_traits>

#include "common/solver_kind.h"

namespace qd::common {

enum class FactorBackend { CholmodLlt, SupernodalLdlt, EigenLlt, EigenLdlt };

class SparseFactor {
 public:
  virtual ~SparseFactor();
  SparseFactor(const SparseFactor&) = delete;
  SparseFactor& operator=(const SparseFactor&) = delete;

  // Factorises the matrix whose lower triangle is `lower` (the pattern of the first call);
  // throws qd::common::Error saying why when it cannot.
  void factorize(const Eigen::SparseMatrix<double>& lower);
  // Solves A x = b with the current factor; b may have several columns (right-hand sides).
  Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const;
  int factorizations() const { return factorizations_; }
  // Floating-point operations of the numeric factorisations so far, by the analysis's count
  // (CHOLMOD's: an LLᵀ takes Σ_j c_j² for c_j the entries of column j of L): the floor the
  // factorisations' time is judged against.
  double flops() const { return flops_; }
  // Entries of the factor L (its nonzeros, the diagonal included): what each triangular pass
  // of a solve must read at least.
  double entries() const { return backend_ ? backend_->entries : 0.0; }
  // The back end, chosen at the first factorisation; substituted: it is not the one asked for,
  // which cannot factorise this class of matrix.
  FactorBackend backend() const { return backend_kind_; }
  bool substituted() const { return substituted_; }

  struct Backend {
    virtual ~Backend() = default;
    virtual bool analyse_and_factorize(const Eigen::SparseMatrix<double>& lower, bool analyse) = 0;
    virtual Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const = 0;
    double flops = 0;    // of one numeric factorisation, set by the analysis
    double entries = 0;  // of L, set by the analysis
  };
  // Σ_j c_j² and Σ_j c_j over the columns of a factor L (its diagonal stored or not).
  static void count_columns(const Eigen::SparseMatrix<double>& L, Backend& counts);
  // Any of Eigen's sparse Cholesky classes (its own or its CHOLMOD wrappers).
  template <typename Solver>
  struct EigenBackend : Backend {
    Solver solver;
    bool analyse_and_factorize(const Eigen::SparseMatrix<double>& lower, bool analyse) override {
      if (analyse) solver.analyzePattern(lower);
      solver.factorize(lower);
      if constexpr (std::is_base_of_v<Eigen::SimplicialCholeskyBase<Solver>, Solver>)
        if (analyse && solver.info() == Eigen::Success)
          count_columns(solver.matrixL().nestedExpression(), *this);
      return solver.info() == Eigen::Success;
    }
    Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const override { return solver.solve(b); }
  };
  using Natural = Eigen::NaturalOrdering<int>;
  using EigenLlt =
      EigenBackend<Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower, Natural>>;
  using EigenLdlt =
      EigenBackend<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Natural>>;

 protected:
  struct Choice {
    FactorBackend kind;
    bool substituted;
  };
  explicit SparseFactor(SolverKind kind) : kind_(kind) {}
  // The back end for `kind_` and a matrix of `unknowns` rows.
  virtual Choice choose(long unknowns) const = 0;
  virtual std::unique_ptr<Backend> make(FactorBackend kind) const = 0;
  // Why a factorisation failed, e.g. "is not positive definite".
  virtual const char* failure() const = 0;
  // In a build without CHOLMOD, for a back end that needs it.
  [[noreturn]] static void throw_no_cholmod();
  SolverKind kind_;

 private:
  std::unique_ptr<Backend> backend_;
  FactorBackend backend_kind_ = FactorBackend::EigenLdlt;
  bool substituted_ = false;
  int factorizations_ = 0;
  double flops_ = 0;
};

}  // namespace qd::common
