#include "approximate/solve_strategy.h"

#include "approximate/common_names.h"
#include "common/conjugate_gradients.h"
#include "common/stage_timer.h"
#include "common/symmetric_product.h"
#include "common/vertex_order.h"

namespace qd::approximate {
namespace {

// What a solve reads at least, in bytes: each value of a factor L once per triangular pass, two
// passes a solve; each stored value of M once per product (the memory bound of a solve).
constexpr double kValueBytes = 8;
double pass_bytes(double entries) { return 2 * kValueBytes * entries; }

}  // namespace

SolveStrategy::SolveStrategy(const Params& params, long unknowns, bool quasi_definite,
                             const BlockPattern& pattern, StageTimes& times,
                             std::shared_ptr<SharedAnalysis> analysis)
    : solver_(params.solver),
      threads_(params.threads),
      iterative_(!quasi_definite &&
                 (params.method == SolveMethod::Iterative ||
                  (params.method == SolveMethod::Auto && unknowns >= kIterativeFromUnknowns))),
      pattern_(pattern),
      times_(times),
      positive_(params.solver),
      quasi_(params.solver, std::move(analysis)) {}

int SolveStrategy::factorizations() const {
  return positive_.factorizations() + quasi_.factorizations() + scalar_factorizations_;
}

double SolveStrategy::factorization_flops() const {
  return positive_.flops() + quasi_.flops() + scalar_flops_;
}

Eigen::VectorXd SolveStrategy::solve(const Eigen::SparseMatrix<double>& M, const Eigen::VectorXd& b,
                                     const std::function<Eigen::VectorXd()>& start,
                                     const std::function<std::vector<Vec3>()>& normals) {
  return iterative_ ? solve_iteratively(M, b, start, normals) : solve_directly(M, b);
}

const Eigen::SparseMatrix<double>& SolveStrategy::in_factor_order(
    const Eigen::SparseMatrix<double>& M) {
  if (pattern_.blocks() < kLeastFillFromBlocks) return M;
  if (factor_order_.size() == 0) {
    const std::vector<int> rank =
        common::fill_reducing_rank(pattern_, common::FillOrder::LeastFill);
    factor_order_.resize(M.rows());
    for (int k = 0; k < pattern_.blocks(); ++k)
      for (int d = 0; d < 3; ++d)
        factor_order_.indices()[3 * k + d] = 3 * rank[static_cast<size_t>(k)] + d;
  }
  Eigen::SparseMatrix<double> lower(M.rows(), M.cols());
  lower.selfadjointView<Eigen::Lower>() =
      M.selfadjointView<Eigen::Lower>().twistedBy(factor_order_);
  reordered_ = Eigen::SparseMatrix<double>(lower.transpose()).transpose();  // sorted columns
  return reordered_;
}

Eigen::VectorXd SolveStrategy::solve_directly(const Eigen::SparseMatrix<double>& M,
                                              const Eigen::VectorXd& b) {
  if (!factor_current_) {  // new targets: a numeric factorisation (analysis reused)
    StageTimer timer(times_.factorization);
    positive_.factorize(in_factor_order(M));
    factor_current_ = true;
  }
  StageTimer timer(times_.solve);
  times_.solve_bytes += pass_bytes(positive_.entries());
  if (factor_order_.size() == 0) return positive_.solve(b);
  return factor_order_.transpose() * positive_.solve(factor_order_ * b);
}

Eigen::VectorXd SolveStrategy::solve_quasi_definite(const Eigen::SparseMatrix<double>& K,
                                                    const Eigen::VectorXd& c) {
  if (!factor_current_) {
    StageTimer timer(times_.factorization);
    quasi_.factorize(K);
    factor_current_ = true;
  }
  StageTimer timer(times_.solve);
  times_.solve_bytes += pass_bytes(quasi_.entries());
  return quasi_.solve(c);
}

Eigen::VectorXd SolveStrategy::solve_iteratively(
    const Eigen::SparseMatrix<double>& M, const Eigen::VectorXd& b,
    const std::function<Eigen::VectorXd()>& start,
    const std::function<std::vector<Vec3>()>& normals) {
  Eigen::VectorXd x = start();  // the correction starts at zero
  const auto multiply = [&](const Eigen::VectorXd& p) -> Eigen::VectorXd {
    times_.solve_bytes += kValueBytes * static_cast<double>(M.nonZeros());
    return common::symmetric_product(M, p, threads_);
  };
  const auto precondition = [this](const Eigen::VectorXd& r) {
    times_.solve_bytes += pass_bytes(preconditioner_->entries());
    return preconditioner_->apply(r);
  };
  if (!preconditioner_ || preconditioner_stale_) {
    StageTimer timer(times_.factorization);
    const std::vector<Vec3> frame_normals = normals();
    if (!preconditioner_)
      preconditioner_ = std::make_unique<FramePreconditioner>(pattern_, solver_, threads_);
    preconditioner_->build(M, frame_normals);
    scalar_factorizations_ = preconditioner_->factorizations();
    scalar_flops_ = preconditioner_->flops();
  }
  preconditioner_stale_ = false;
  CgOutcome cg;
  {
    StageTimer timer(times_.solve);
    cg = conjugate_gradients(multiply, precondition, b, x, kCgTolerance, kCgIterations,
                             &last_solution_);
  }
  last_solution_ = x;
  times_.cg_iterations += cg.iterations;
  if (!cg.converged) ++times_.cg_truncated;  // its iterate is the step all the same
  return x;
}

}  // namespace qd::approximate
