#include "deformation_system.h"

#include <Eigen/Dense>

#include "anchor_weights.h"

namespace qd {
namespace {

// Shape and centroid rows of Eq. (13) per coordinate, as a 3×3 corner matrix: Σ rᵀr over the
// rows (−1,1,0), (−1,0,1) of Eq. (5) and (1,1,1)/3 of Eq. (6).
Eigen::Matrix3d shape_block() {
  Eigen::Matrix3d L;
  L << 2, -1, -1, -1, 1, 0, -1, 0, 1;
  return L + Eigen::Matrix3d::Constant(1.0 / 9.0);
}

// 3×3 block of M coupling corners p and q of a face with target n (developability rows give
// +2·w²nnᵀ on the diagonal and −w²nnᵀ off it, since every corner pair is an edge).
Eigen::Matrix3d corner_block(const Eigen::Matrix3d& L, const Eigen::Matrix3d& N, int p, int q) {
  return L(p, q) * Eigen::Matrix3d::Identity() + (p == q ? 2.0 : -1.0) * N;
}

}  // namespace

DeformationSystem::DeformationSystem(const GroupMesh& group, double weight, double anchor,
                                     double ae)
    : g_(group), w_(weight) {
  const size_t n = g_.fixed.size();
  unknown_.assign(n, -1);
  for (size_t v = 0; v < n; ++v)
    if (!g_.fixed[v]) unknown_[v] = unknowns_++;
  const std::vector<double> mls = mls_weights(g_.V0, g_.fixed, ae);
  anchor2_.resize(n);
  for (size_t v = 0; v < n; ++v) anchor2_[v] = anchor * anchor * mls[v] * mls[v];
}

void DeformationSystem::set_targets(const std::vector<Vec3>& targets) {
  targets_ = targets;
  const Eigen::Matrix3d L = shape_block();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<size_t>(g_.solve_faces) * 81 + static_cast<size_t>(unknowns_) * 3);
  for (Eigen::Index f = 0; f < g_.solve_faces; ++f) {
    const Vec3& n = targets_[static_cast<size_t>(f)];
    const Eigen::Matrix3d N = w_ * w_ * n * n.transpose();
    for (int p = 0; p < 3; ++p) {
      const int bp = unknown_[static_cast<size_t>(g_.F(f, p))];
      if (bp < 0) continue;
      for (int q = 0; q < 3; ++q) {
        const int bq = unknown_[static_cast<size_t>(g_.F(f, q))];
        if (bq < 0 || bq > bp) continue;  // lower triangle only
        const Eigen::Matrix3d B = corner_block(L, N, p, q);
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            if (3 * bq + j <= 3 * bp + i) entries.emplace_back(3 * bp + i, 3 * bq + j, B(i, j));
      }
    }
  }
  for (size_t v = 0; v < unknown_.size(); ++v)
    if (unknown_[v] >= 0)
      for (int i = 0; i < 3; ++i)
        entries.emplace_back(3 * unknown_[v] + i, 3 * unknown_[v] + i, anchor2_[v]);
  M_.resize(3 * unknowns_, 3 * unknowns_);
  M_.setFromTriplets(entries.begin(), entries.end());
  cholesky_.factorize(M_);
}

Eigen::VectorXd DeformationSystem::rhs(const Positions& ref) const {
  const Eigen::Matrix3d L = shape_block();
  Eigen::VectorXd b = Eigen::VectorXd::Zero(3 * unknowns_);
  for (Eigen::Index f = 0; f < g_.solve_faces; ++f) {
    Vec3 x[3];
    for (int c = 0; c < 3; ++c) x[c] = ref.row(g_.F(f, c)).transpose();
    const Vec3 e12 = x[1] - x[0], e13 = x[2] - x[0];  // c of Eq. (13): reference edges
    const Vec3 centroid = (x[0] + x[1] + x[2]) / 3.0;  // and centroid
    const Vec3 atc[3] = {-e12 - e13 + centroid / 3.0, e12 + centroid / 3.0, e13 + centroid / 3.0};
    const Eigen::Matrix3d N = w_ * w_ * targets_[static_cast<size_t>(f)] *
                              targets_[static_cast<size_t>(f)].transpose();
    for (int p = 0; p < 3; ++p) {
      const int bp = unknown_[static_cast<size_t>(g_.F(f, p))];
      if (bp < 0) continue;
      Vec3 row = atc[p];
      for (int q = 0; q < 3; ++q)  // eliminate the constrained corners (they stay at V0)
        if (unknown_[static_cast<size_t>(g_.F(f, q))] < 0)
          row -= corner_block(L, N, p, q) * g_.V0.row(g_.F(f, q)).transpose();
      b.segment<3>(3 * bp) += row;
    }
  }
  for (size_t v = 0; v < unknown_.size(); ++v)
    if (unknown_[v] >= 0)
      b.segment<3>(3 * unknown_[v]) += anchor2_[v] * g_.V0.row(static_cast<Eigen::Index>(v)).transpose();
  return b;
}

Positions DeformationSystem::solve(const Positions& ref) const {
  const Eigen::VectorXd x = cholesky_.solve(rhs(ref));
  Positions out = ref;
  for (size_t v = 0; v < unknown_.size(); ++v)
    if (unknown_[v] >= 0)
      out.row(static_cast<Eigen::Index>(v)) = x.segment<3>(3 * unknown_[v]).transpose();
  return out;
}

}  // namespace qd
