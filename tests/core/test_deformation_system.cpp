// The sparse normal equations of Step 2 equal a dense, literal assembly of Eq. (13) with summed
// vertex columns (§5.3), exact elimination of constrained vertices and the Eq. (15) anchors.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <random>

#include "approximate/anchor_weights.h"
#include "approximate/deformation_system.h"
#include "approximate/group_mesh.h"
#include "common/conjugate_gradients.h"
#include "common/mesh.h"
#include "test_meshes.h"

namespace qd {
namespace {

using namespace qd::approximate;
using namespace qd::common;

struct Fixture {
  Problem p;
  GroupMesh g;
  std::vector<Vec3> targets;
  Positions ref;
  // A coarse bumpy cylinder (`around` faces around, half as many rings) with targets at
  // random, or (smooth) a finer one whose targets are its faces' own normals, as Step 1 gives a
  // near-developable patch.
  explicit Fixture(bool smooth = false, int around = 6)
      : p(smooth ? test::bumpy_cylinder(32, 4, 0.02)
                 : test::bumpy_cylinder(around, around / 2, 0.2)) {
    const size_t nv = static_cast<size_t>(p.V.rows()), nf = static_cast<size_t>(p.F.rows());
    std::vector<int> faces(nf);
    for (size_t f = 0; f < nf; ++f) faces[f] = static_cast<int>(f);
    std::vector<char> constrained(nv, 0), interior(nv, 1);
    constrained[0] = constrained[7] = constrained[20] = 1;
    g = extract_group(p.V, p.F, faces, std::vector<int>(nf, 0), constrained, interior,
                      VertexFaces(p.F, p.V.rows()), p.params);
    std::mt19937 rng(7);
    std::normal_distribution<double> gauss;
    for (size_t f = 0; f < nf; ++f)
      targets.push_back(smooth ? face_normal(g.V0, g.F, static_cast<int>(f))
                               : Vec3(gauss(rng), gauss(rng), gauss(rng)).normalized());
    ref = g.V0;
    for (Eigen::Index v = 0; v < ref.rows(); ++v)
      if (!g.fixed[static_cast<size_t>(v)])
        ref.row(v) += 0.05 * Eigen::RowVector3d(gauss(rng), gauss(rng), gauss(rng));
  }
};

// Dense A (12|T| + 3|V_free| rows, 3|V| columns) and c, built row by row from Eq. (13) and the
// anchor rows, then the constrained columns moved to the right-hand side.
void dense_system(const Fixture& s, double w, double alpha, double ae, Eigen::MatrixXd& A_free,
                  Eigen::VectorXd& c_eff) {
  const Eigen::Index nv = s.g.V0.rows(), nf = s.g.F.rows();
  const std::vector<double> mls = mls_weights(s.g.V0, s.g.fixed, ae);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(12 * nf + 3 * nv, 3 * nv);
  Eigen::VectorXd c = Eigen::VectorXd::Zero(A.rows());
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  for (Eigen::Index f = 0; f < nf; ++f) {
    const int v[3] = {s.g.F(f, 0), s.g.F(f, 1), s.g.F(f, 2)};
    const Eigen::RowVector3d H = w * s.targets[static_cast<size_t>(f)].transpose();
    const Eigen::Index r = 12 * f;
    for (int e = 0; e < 3; ++e) {  // w·n·(v_{e+1} − v_e) = 0
      A.block(r + e, 3 * v[(e + 1) % 3], 1, 3) += H;
      A.block(r + e, 3 * v[e], 1, 3) -= H;
    }
    const Vec3 x1 = s.ref.row(v[0]), x2 = s.ref.row(v[1]), x3 = s.ref.row(v[2]);
    A.block(r + 3, 3 * v[1], 3, 3) += I;
    A.block(r + 3, 3 * v[0], 3, 3) -= I;
    c.segment<3>(r + 3) = x2 - x1;
    A.block(r + 6, 3 * v[2], 3, 3) += I;
    A.block(r + 6, 3 * v[0], 3, 3) -= I;
    c.segment<3>(r + 6) = x3 - x1;
    for (int k = 0; k < 3; ++k) A.block(r + 9, 3 * v[k], 3, 3) += I / 3.0;
    c.segment<3>(r + 9) = (x1 + x2 + x3) / 3.0;
  }
  for (Eigen::Index v = 0; v < nv; ++v) {
    if (s.g.fixed[static_cast<size_t>(v)]) continue;
    const double a = alpha * mls[static_cast<size_t>(v)];
    A.block(12 * nf + 3 * v, 3 * v, 3, 3) = a * I;
    c.segment<3>(12 * nf + 3 * v) = a * s.g.V0.row(v).transpose();
  }
  std::vector<Eigen::Index> free_cols;
  c_eff = c;
  for (Eigen::Index v = 0; v < nv; ++v)
    for (int d = 0; d < 3; ++d) {
      if (s.g.fixed[static_cast<size_t>(v)])
        c_eff -= A.col(3 * v + d) * s.g.V0(v, d);
      else
        free_cols.push_back(3 * v + d);
    }
  A_free.resize(A.rows(), static_cast<Eigen::Index>(free_cols.size()));
  for (size_t k = 0; k < free_cols.size(); ++k)
    A_free.col(static_cast<Eigen::Index>(k)) = A.col(free_cols[k]);
}

// The sparse system and its dense twin for one set of weights, the twin's columns put in the
// system's unknown order (free vertices numbered in a fill-reducing order, 3 coordinates each).
Params params(double w, double alpha, SolverKind solver, SolveMethod method) {
  Params p;
  p.weight = w;
  p.anchor = alpha;
  p.solver = solver;
  p.method = method;
  p.threads = 2;
  return p;
}

// The free vertices' positions X as the system's unknown vector (its order, 3 coordinates each).
Eigen::VectorXd unknown_vector(const DeformationSystem& sys, const Positions& X) {
  Eigen::VectorXd x(sys.matrix().rows());
  for (size_t v = 0; v < sys.unknown().size(); ++v)
    if (sys.unknown()[v] >= 0)
      x.segment<3>(3 * sys.unknown()[v]) = X.row(static_cast<Eigen::Index>(v)).transpose();
  return x;
}

struct Both {
  Fixture s;
  DeformationSystem sys;
  Eigen::MatrixXd A;
  Eigen::VectorXd c;
  // defect_rows: every free vertex also gets an angle-defect row (angle_defect.h, default weight),
  // linearised at the reference positions.
  Both(double w, double alpha, double ae, SolverKind solver = SolverKind::Auto,
       SolveMethod method = SolveMethod::Direct, bool smooth = false, bool defect_rows = false)
      : s(smooth), sys(s.g, params(w, alpha, solver, method), ae, rows_of(s, defect_rows)) {
    sys.set_rows(s.targets, defect_rows
                                ? sys.linearise_defects_at(s.ref, vertex_angles(s.ref, s.g.F))
                                : DefectLinearisation{});
    Eigen::MatrixXd by_vertex;
    dense_system(s, w, alpha, ae, by_vertex, c);
    if (defect_rows) append_defect_rows(by_vertex);
    A.resize(by_vertex.rows(), by_vertex.cols());
    Eigen::Index k = 0;
    for (size_t v = 0; v < sys.unknown().size(); ++v) {
      if (sys.unknown()[v] < 0) continue;
      for (int d = 0; d < 3; ++d) A.col(3 * sys.unknown()[v] + d) = by_vertex.col(3 * k + d);
      ++k;
    }
  }
  static std::vector<char> rows_of(const Fixture& s, bool defect_rows) {
    if (!defect_rows) return {};
    std::vector<char> rows(s.g.fixed.size());
    for (size_t v = 0; v < rows.size(); ++v) rows[v] = !s.g.fixed[v];
    return rows;
  }
  // The rows s_r·∇K_r·x' = s_r·(∇K_r·x_ref − K_r) over the free vertices, in vertex order.
  void append_defect_rows(Eigen::MatrixXd& by_vertex) {
    const VertexFaces incident(s.g.F, s.g.V0.rows());
    const DefectStars rows = defect_stars(s.g, incident, rows_of(s, true), Params().defect_weight);
    const DefectLinearisation lin =
        linearise_defects(rows, s.g, incident, s.ref, vertex_angles(s.ref, s.g.F));
    std::vector<int> column(s.g.fixed.size(), -1);
    int k = 0;
    for (size_t v = 0; v < column.size(); ++v)
      if (!s.g.fixed[v]) column[v] = 3 * k++;
    const Eigen::Index first = by_vertex.rows(), n = static_cast<Eigen::Index>(rows.vertex.size());
    by_vertex.conservativeResize(first + n, Eigen::NoChange);
    by_vertex.bottomRows(n).setZero();
    c.conservativeResize(first + n);
    for (size_t r = 0; r < rows.vertex.size(); ++r) {
      const auto row = first + static_cast<Eigen::Index>(r);
      c[row] = -rows.weight[r] * lin.defect[r];
      for (int q = rows.start[r]; q < rows.start[r + 1]; ++q) {
        const int u = rows.star[static_cast<size_t>(q)];
        if (column[static_cast<size_t>(u)] < 0) continue;
        const Vec3 g = rows.weight[r] * lin.gradient[static_cast<size_t>(q)];
        by_vertex.block<1, 3>(row, column[static_cast<size_t>(u)]) = g.transpose();
        c[row] += g.dot(s.ref.row(u).transpose());
      }
    }
  }
  // Unknown vector of positions X, in the system's order.
  Eigen::VectorXd free_vector(const Positions& X) const { return unknown_vector(sys, X); }
};

TEST(DeformationSystem, SparseEqualsDenseAssembly) {
  Both b(7.0, 3.0, 0.4);
  auto& [s, sys, A, c] = b;

  const Eigen::MatrixXd lower = Eigen::MatrixXd(sys.matrix());
  const Eigen::MatrixXd M =
      lower + lower.transpose() - Eigen::MatrixXd(lower.diagonal().asDiagonal());
  const Eigen::MatrixXd expected = A.transpose() * A;
  ASSERT_EQ(M.rows(), expected.rows());
  EXPECT_LT((M - expected).norm(), 1e-9 * expected.norm());
  const Eigen::VectorXd rhs = sys.rhs(s.ref), eb = A.transpose() * c;
  EXPECT_LT((rhs - eb).norm(), 1e-9 * eb.norm());
}

class EverySolver : public ::testing::TestWithParam<SolverKind> {};

TEST_P(EverySolver, SolveIsTheLeastSquaresMinimiser) {
  Both b(30.0, 10.0, 0.4, GetParam());
  auto& [s, sys, A, c] = b;
  const Eigen::VectorXd x = A.colPivHouseholderQr().solve(c);
  const Positions X = sys.solve(s.ref);
  for (Eigen::Index v = 0; v < X.rows(); ++v) {
    const int k = sys.unknown()[static_cast<size_t>(v)];
    if (k < 0) {
      EXPECT_EQ(X.row(v), s.g.V0.row(v)) << "constrained vertex " << v << " moved";
      continue;
    }
    EXPECT_LT((X.row(v).transpose() - x.segment<3>(3 * k)).norm(), 1e-8);
  }
}

// Angle-defect rows, solved through the quasi-definite system K = [[M, Cᵀ], [C, −I]], give the
// least-squares minimiser of all the rows together, whichever back end factorises K.
TEST_P(EverySolver, DefectRowsSolveIsTheLeastSquaresMinimiser) {
  Both b(30.0, 10.0, 0.4, GetParam(), SolveMethod::Direct, false, true);
  auto& [s, sys, A, c] = b;
  ASSERT_TRUE(sys.has_defect_rows());
  const Eigen::VectorXd exact = A.colPivHouseholderQr().solve(c);
  Both plain(30.0, 10.0, 0.4, GetParam());  // same unknown order: defect rows leave M's pattern
  const Eigen::VectorXd without = plain.A.colPivHouseholderQr().solve(plain.c);
  ASSERT_GT((exact - without).cwiseAbs().maxCoeff(), 1e-3)
      << "the defect rows change the minimiser";
  EXPECT_LT((b.free_vector(sys.solve(s.ref)) - exact).cwiseAbs().maxCoeff(), 1e-8);
}

// Conjugate gradients with the frame preconditioner reach the same minimiser, to the stated
// tolerance relative to the correction, when the targets follow the surface.
TEST_P(EverySolver, IterativeSolveIsTheMinimiserToItsTolerance) {
  Both b(30.0, 10.0, 0.4, GetParam(), SolveMethod::Iterative, true);
  auto& [s, sys, A, c] = b;
  const Eigen::VectorXd exact = A.colPivHouseholderQr().solve(c);
  const Eigen::VectorXd x = b.free_vector(sys.solve(s.ref)), x0 = b.free_vector(s.ref);
  EXPECT_GT(sys.times().cg_iterations, 0);
  EXPECT_LT(sys.times().cg_iterations, kCgIterations);
  EXPECT_EQ(sys.times().factorizations, 2) << "two scalar factors, M never factorised";
  const Eigen::MatrixXd lower = Eigen::MatrixXd(sys.matrix());
  const Eigen::MatrixXd M =
      lower + lower.transpose() - Eigen::MatrixXd(lower.diagonal().asDiagonal());
  const auto energy = [&](const Eigen::VectorXd& e) { return std::sqrt(e.dot(M * e)); };
  EXPECT_LT(energy(x - exact), 10 * kCgTolerance * energy(exact - x0));
}

// Targets at random to the faces defeat the frames: CG sees it is too slow and gives up early.
// Its iterate is the step all the same (a truncated solve): nearer the direct solution in M's
// energy norm than the start, with M never factorised, and the next solve runs CG again. The
// cylinder is finer than Both's: on a small one CG reaches its tolerance (1e-2) before the
// give-up rule applies.
TEST_P(EverySolver, IterativeSolveKeepsCgsIterateWhereCgStalls) {
  const Fixture s(false, 48);
  DeformationSystem iterative(s.g, params(1000.0, 10.0, GetParam(), SolveMethod::Iterative), 0.4);
  DeformationSystem direct(s.g, params(1000.0, 10.0, GetParam(), SolveMethod::Direct), 0.4);
  iterative.set_rows(s.targets);
  direct.set_rows(s.targets);
  const Eigen::VectorXd exact = unknown_vector(iterative, direct.solve(s.ref));
  const Eigen::VectorXd start = unknown_vector(iterative, s.ref);
  const Eigen::VectorXd x = unknown_vector(iterative, iterative.solve(s.ref));
  const Eigen::SparseMatrix<double> M = iterative.matrix().selfadjointView<Eigen::Lower>();
  const auto energy = [&](const Eigen::VectorXd& e) { return std::sqrt(e.dot(M * e)); };
  const int tried = iterative.times().cg_iterations;
  EXPECT_GE(tried, kCgPatience);
  EXPECT_LT(tried, kCgIterations) << "gave up before the last allowed iteration";
  EXPECT_EQ(iterative.times().cg_truncated, 1);
  EXPECT_GT(energy(x - exact), kCgTolerance * energy(exact - start)) << "CG did not converge";
  EXPECT_LT(energy(x - exact), 0.5 * energy(exact - start)) << "a step toward the solution";
  EXPECT_EQ(iterative.times().factorizations, 2) << "two scalar factors, M never factorised";
  iterative.solve(s.ref);
  EXPECT_GT(iterative.times().cg_iterations, tried) << "the next solve runs CG too";
  EXPECT_EQ(iterative.times().factorizations, 2);
}

INSTANTIATE_TEST_SUITE_P(Solvers, EverySolver,
                         ::testing::Values(SolverKind::Auto, SolverKind::Cholmod,
                                           SolverKind::EigenLLT, SolverKind::EigenLDLT));

// The unknowns are numbered in a fill-reducing order: a permutation of the free vertices.
TEST(DeformationSystem, UnknownsArePermutedFreeVertices) {
  Both b(30.0, 10.0, 0.4);
  std::vector<int> seen;
  for (size_t v = 0; v < b.sys.unknown().size(); ++v) {
    EXPECT_EQ(b.sys.unknown()[v] < 0, static_cast<bool>(b.s.g.fixed[v])) << "vertex " << v;
    if (b.sys.unknown()[v] >= 0) seen.push_back(b.sys.unknown()[v]);
  }
  std::sort(seen.begin(), seen.end());
  for (size_t k = 0; k < seen.size(); ++k) EXPECT_EQ(seen[k], static_cast<int>(k));
}

TEST(DeformationSystem, SolveLowersTheObjectiveOfEq14) {
  Both b(30.0, 10.0, 0.4);
  auto& [s, sys, A, c] = b;
  const double at_ref = (A * b.free_vector(s.ref) - c).squaredNorm();
  const double at_solution = (A * b.free_vector(sys.solve(s.ref)) - c).squaredNorm();
  EXPECT_LT(at_solution, 0.5 * at_ref);
}

}  // namespace
}  // namespace qd
