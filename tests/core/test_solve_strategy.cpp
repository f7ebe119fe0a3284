// SolveStrategy: the method chosen by size, a factorisation only for new values, the
// preconditioner rebuilt only for new weights, K's factor reporting a substituted back end, and
// a large factorised M solved in its LeastFill order.
#include <gtest/gtest.h>

#include "approximate/solve_strategy.h"
#include "solver_matrices.h"

namespace qd {
namespace {

using namespace qd::approximate;
using namespace qd::common;

struct System {
  test::Edges edges;
  BlockPattern pattern;
  Eigen::SparseMatrix<double> M;
  Eigen::VectorXd b;
  System(int rows, int cols)
      : edges(test::grid_edges(rows, cols)),
        pattern(lower_pattern(rows * cols, edges)),
        M(test::block_matrix(pattern, edges, Vec3(0, 0, 1), 20.0, 0.3, 0.05)),
        b(Eigen::VectorXd::Random(M.rows())) {}
  Eigen::VectorXd solve(SolveStrategy& s) const {
    const auto start = [&] { return Eigen::VectorXd::Zero(M.rows()).eval(); };
    const auto normals = [&] {
      return std::vector<Vec3>(static_cast<size_t>(pattern.blocks()), Vec3(0, 0, 1));
    };
    return s.solve(M, b, start, normals);
  }
  double residual(const Eigen::VectorXd& x) const {
    return (b - M.selfadjointView<Eigen::Lower>() * x).norm() / b.norm();
  }
};

Params with(SolveMethod method, SolverKind solver = SolverKind::Auto) {
  Params p;
  p.method = method;
  p.solver = solver;
  p.threads = 1;
  return p;
}

TEST(SolveStrategy, DirectFactorisesOnlyNewValues) {
  const System sys(6, 5);
  StageTimes times;
  SolveStrategy s(with(SolveMethod::Direct), sys.M.rows(), false, sys.pattern, times);
  EXPECT_LT(sys.residual(sys.solve(s)), 1e-10);
  sys.solve(s);
  EXPECT_EQ(s.factorizations(), 1);
  s.values_changed();
  sys.solve(s);
  EXPECT_EQ(s.factorizations(), 2);
  EXPECT_EQ(times.cg_iterations, 0);
}

TEST(SolveStrategy, AutoIteratesFromItsThreshold) {
  const System small(6, 5), large(60, 56);  // 90 and 10,080 unknowns
  ASSERT_GE(large.M.rows(), kIterativeFromUnknowns);
  StageTimes small_times, large_times;
  SolveStrategy direct(with(SolveMethod::Auto), small.M.rows(), false, small.pattern, small_times);
  SolveStrategy iterative(with(SolveMethod::Auto), large.M.rows(), false, large.pattern,
                          large_times);
  small.solve(direct);
  const Eigen::VectorXd x = large.solve(iterative);
  EXPECT_EQ(small_times.cg_iterations, 0);
  EXPECT_GT(large_times.cg_iterations, 0);
  EXPECT_EQ(iterative.factorizations(), 2) << "the two scalar factors, not M";
  EXPECT_LT(large.residual(x), 10 * kCgTolerance);
}

TEST(SolveStrategy, RebuildsThePreconditionerForNewWeightsOnly) {
  const System sys(8, 8);
  StageTimes times;
  SolveStrategy s(with(SolveMethod::Iterative), sys.M.rows(), false, sys.pattern, times);
  sys.solve(s);
  s.values_changed();  // new targets: the preconditioner is kept
  sys.solve(s);
  EXPECT_EQ(s.factorizations(), 2);
  s.weights_changed();
  sys.solve(s);
  EXPECT_EQ(s.factorizations(), 4);
}

TEST(SolveStrategy, ALargeFactorisedSystemIsSolvedInALeastFillOrder) {
  const System large(101, 100);  // 10,100 blocks
  ASSERT_GE(large.pattern.blocks(), kLeastFillFromBlocks);
  StageTimes times;
  SolveStrategy s(with(SolveMethod::Direct), large.M.rows(), false, large.pattern, times);
  EXPECT_LT(large.residual(large.solve(s)), 1e-10);
  s.values_changed();  // the permuted pattern's analysis is reused
  EXPECT_LT(large.residual(large.solve(s)), 1e-10);
  EXPECT_EQ(s.factorizations(), 2);
  // The grid's blocks come row by row, a band of 100 blocks: the order found fills far less.
  const double band_flops = 2.0 * large.pattern.blocks() * (3.0 * 101) * (3.0 * 101);
  EXPECT_LT(s.factorization_flops(), 0.5 * band_flops);
}

TEST(SolveStrategy, QuasiDefiniteSystemsAreFactorisedAndSubstitutionsReported) {
  const Eigen::SparseMatrix<double> K = test::random_quasi_definite(40, 10, 2, 5);
  const Eigen::VectorXd c = Eigen::VectorXd::Random(K.rows());
  const BlockPattern none;
  for (const SolverKind kind : {SolverKind::EigenLLT, SolverKind::Auto}) {
    StageTimes times;
    SolveStrategy s(with(SolveMethod::Iterative, kind), K.rows(), true, none, times);
    const Eigen::VectorXd z = s.solve_quasi_definite(K, c);
    EXPECT_LT((c - K.selfadjointView<Eigen::Lower>() * z).norm(), 1e-10 * c.norm());
    EXPECT_EQ(s.substituted(), kind == SolverKind::EigenLLT);
    EXPECT_EQ(s.factorizations(), 1);
  }
}

}  // namespace
}  // namespace qd
