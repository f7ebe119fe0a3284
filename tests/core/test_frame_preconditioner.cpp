// FramePreconditioner on small block systems: exact where M splits along one normal, an SPD
// preconditioner that lets CG solve a coupled SPD system to tolerance, and a failure on an
// indefinite M.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "approximate/frame_preconditioner.h"
#include "common/conjugate_gradients.h"
#include "common/error.h"
#include "solver_matrices.h"

namespace qd {
namespace {

using namespace qd::approximate;
using namespace qd::common;

struct Grid {
  test::Edges edges = test::grid_edges(8, 7);
  BlockPattern pattern = lower_pattern(56, edges);
};

TEST(FramePreconditioner, IsExactWhenMSplitsAlongTheNormals) {
  const Grid g;
  const Vec3 nu(0.3, -0.2, 0.9);
  const Eigen::SparseMatrix<double> M = test::block_matrix(g.pattern, g.edges, nu, 100.0, 0.5, 0.0);
  for (const SolverKind kind : {SolverKind::Cholmod, SolverKind::EigenLDLT}) {
    FramePreconditioner P(g.pattern, kind, 2);
    P.build(M, std::vector<Vec3>(56, 2.0 * nu));
    const Eigen::VectorXd x = Eigen::VectorXd::Random(M.rows());
    const Eigen::VectorXd y = P.apply(M.selfadjointView<Eigen::Lower>() * x);
    EXPECT_LT((y - x).norm(), 1e-9 * x.norm());
    EXPECT_EQ(P.factorizations(), 2);
  }
}

TEST(FramePreconditioner, LetsCgSolveACoupledSystem) {
  const Grid g;
  const Eigen::SparseMatrix<double> M =
      test::block_matrix(g.pattern, g.edges, Vec3(0, 0, 1), 50.0, 0.2, 0.1);
  std::vector<Vec3> normals(56);  // normals off M's own, and one zero (any frame)
  for (size_t k = 0; k < normals.size(); ++k)
    normals[k] = Vec3(0.1 * std::sin(k), 0.1 * std::cos(k), 1.0);
  normals[3] = Vec3::Zero();
  FramePreconditioner P(g.pattern, SolverKind::Auto, 1);
  P.build(M, normals);
  const Eigen::VectorXd r = Eigen::VectorXd::Random(M.rows()),
                        s = Eigen::VectorXd::Random(M.rows());
  const Eigen::VectorXd Pr = P.apply(r), Ps = P.apply(s);
  EXPECT_GT(r.dot(Pr), 0.0);                                        // positive
  EXPECT_NEAR(s.dot(Pr), r.dot(Ps), 1e-10 * Pr.norm() * s.norm());  // symmetric
  const auto multiply = [&](const Eigen::VectorXd& p) -> Eigen::VectorXd {
    return M.selfadjointView<Eigen::Lower>() * p;
  };
  const Eigen::VectorXd b = Eigen::VectorXd::Random(M.rows());
  Eigen::VectorXd x = Eigen::VectorXd::Zero(M.rows());
  const CgOutcome cg = conjugate_gradients(
      multiply, [&](const Eigen::VectorXd& v) { return P.apply(v); }, b, x, 1e-10, 200);
  EXPECT_TRUE(cg.converged);
  EXPECT_LT((b - multiply(x)).norm(), 1e-6 * b.norm());
}

TEST(FramePreconditioner, ReportsAnIndefiniteSystem) {
  const Grid g;
  const Eigen::SparseMatrix<double> M =
      test::block_matrix(g.pattern, g.edges, Vec3(0, 0, 1), 1.0, -0.5, 0.0);
  FramePreconditioner P(g.pattern, SolverKind::Auto, 1);
  EXPECT_THROW(P.build(M, std::vector<Vec3>(56, Vec3(0, 0, 1))), Error);
}

}  // namespace
}  // namespace qd
