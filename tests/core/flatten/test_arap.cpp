// ARAP's local/global iterations: back to the isometry from a disturbed start, the iteration
// cap and the per-iteration callback.
#include <gtest/gtest.h>

#include <random>

#include "flatten/arap.h"
#include "flatten/cotangent_laplacian.h"
#include "flatten_meshes.h"

namespace {

using namespace qd::common;
using namespace qd::flatten;

struct Strip {
  qd::test::GridMesh m = qd::test::cylinder(20, 6, 1.0, 1.0, 2.0);  // open: a disk
  qd::flatten::FlatTriangles g = qd::flatten::flat_triangles(m.V, m.F);
  Eigen::SparseMatrix<double> L =
      qd::flatten::cotangent_laplacian(m.F, g, static_cast<int>(m.V.rows()));
  // A start far from the development: the 3D x, z coordinates, jittered.
  Eigen::MatrixX2d start() const {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> jitter(-0.02, 0.02);
    Eigen::MatrixX2d uv(m.V.rows(), 2);
    for (int v = 0; v < m.V.rows(); ++v)
      uv.row(v) << m.V(v, 0) + jitter(random), m.V(v, 2) + jitter(random);
    return uv;
  }
};

TEST(Arap, ConvergesToTheIsometryOfADevelopableStrip) {
  const Strip s;
  Eigen::MatrixX2d uv = s.start();
  const qd::flatten::ArapOutcome out =
      qd::flatten::arap(s.m.F, s.g, s.L, uv, {2000, 1e-14, qd::common::SolverKind::Auto});
  EXPECT_LT(out.energy, 1e-10);
  for (int f = 0; f < s.m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = s.m.F(f, k), b = s.m.F(f, (k + 1) % 3);
      const double d3 = (s.m.V.row(a) - s.m.V.row(b)).norm();
      EXPECT_NEAR((uv.row(a) - uv.row(b)).norm(), d3, 1e-4 * d3);
    }
}

TEST(Arap, StopsAtTheCapAndReportsEachIteration) {
  const Strip s;
  Eigen::MatrixX2d uv = s.start();
  std::vector<int> seen;
  const qd::flatten::ArapOutcome out =
      qd::flatten::arap(s.m.F, s.g, s.L, uv, {3, 0.0, qd::common::SolverKind::EigenLDLT},
                        [&](int k) { seen.push_back(k); });
  EXPECT_EQ(out.iterations, 3);
  EXPECT_EQ(out.stop_reason, "iteration cap");
  EXPECT_EQ(seen, (std::vector<int>{1, 2, 3}));
}

TEST(Arap, EnergyNeverRises) {
  const Strip s;
  Eigen::MatrixX2d uv = s.start();
  double previous = INFINITY;
  for (int cap = 1; cap <= 6; ++cap) {
    Eigen::MatrixX2d again = s.start();
    const qd::flatten::ArapOutcome out =
        qd::flatten::arap(s.m.F, s.g, s.L, again, {cap, 0.0, qd::common::SolverKind::Auto});
    EXPECT_LE(out.energy, previous * (1 + 1e-12));
    previous = out.energy;
  }
}

}  // namespace
