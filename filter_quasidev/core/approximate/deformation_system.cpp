#include "approximate/deformation_system.h"

#include <Eigen/Dense>
#include <algorithm>

#include "approximate/common_names.h"
#include "common/parallel_for.h"
#include "common/stage_timer.h"

namespace qd::approximate {
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

DeformationSystem::DeformationSystem(const GroupMesh& group, const Params& params, double ae,
                                     const std::vector<char>& defect_rows)
    : DeformationSystem(group, params, SystemLayouts(group, params, ae).get(defect_rows)) {}

DeformationSystem::DeformationSystem(const GroupMesh& group, const Params& params,
                                     SystemLayout layout)
    : g_(group),
      w_(params.weight),
      layout_(std::move(layout)),
      m_(*layout_.matrix),
      defects_(layout_.augmented ? layout_.augmented->defects : DefectStars{}),
      M_(m_.M),
      threads_(params.threads),
      K_(layout_.augmented ? layout_.augmented->K : Eigen::SparseMatrix<double>()) {
  strategy_.emplace(params, 3L * m_.blocks, layout_.augmented != nullptr, m_.pattern, times_,
                    layout_.augmented ? layout_.augmented->analysis : nullptr);
  defects_.weigh(params.defect_weight);  // the layout may be shared at another w_d (group_run.h)
}

void DeformationSystem::scale_developability(double factor) {
  w_ *= factor;
  for (double& s : defects_.weight) s *= factor;
  strategy_->weights_changed();
}

// Each block column is summed by the thread that owns it, from the corners of its vertex: its
// diagonal block, and the off-diagonal blocks whose other vertex comes later in the order.
void DeformationSystem::set_rows(const std::vector<Vec3>& targets,
                                 const DefectLinearisation& defects) {
  StageTimer timer(times_.assembly);
  targets_ = targets;
  linearised_ = defects;
  const Eigen::Matrix3d L = shape_block();
  double* value = M_.valuePtr();
  const int* outer = M_.outerIndexPtr();
  parallel_ranges(static_cast<size_t>(m_.blocks), static_cast<size_t>(threads_), kRangeChunk,
                  [&](size_t first, size_t last) {
                    for (int k = static_cast<int>(first); k < static_cast<int>(last); ++k) {
                      std::fill(value + outer[3 * k], value + outer[3 * k + 3], 0.0);
                      Eigen::Matrix3d diagonal =
                          m_.anchor2[static_cast<size_t>(k)] * Eigen::Matrix3d::Identity();
                      const int v = m_.block_vertex[static_cast<size_t>(k)];
                      for (int c = m_.incident.start[static_cast<size_t>(v)];
                           c < m_.incident.start[static_cast<size_t>(v) + 1]; ++c) {
                        const int f = m_.incident.faces[static_cast<size_t>(c)];
                        if (f >= g_.solve_faces) continue;  // a ring face: measured, not solved
                        const int p = g_.F(f, 0) == v ? 0 : g_.F(f, 1) == v ? 1 : 2;
                        const Vec3& n = targets_[static_cast<size_t>(f)];
                        const Eigen::Matrix3d N = w_ * w_ * n * n.transpose();
                        diagonal += corner_block(L, N, p, p);
                        for (int e = 0; e < 3; ++e) {
                          const int a = kCornerPairs[e][0], b = kCornerPairs[e][1];
                          const int s = m_.face_slot[static_cast<size_t>(3 * f + e)];
                          if (s < 0 || (a != p && b != p)) continue;
                          const int other =
                              m_.unknown[static_cast<size_t>(g_.F(f, a == p ? b : a))];
                          if (other < k)
                            continue;  // that block belongs to the other vertex's column
                          const Eigen::Matrix3d B = corner_block(L, N, a, b);  // symmetric
                          for (int j = 0; j < 3; ++j)
                            for (int i = 0; i < 3; ++i)
                              value[block_entry(outer, m_.pattern, k, s, i, j)] += B(i, j);
                        }
                      }
                      for (int j = 0; j < 3; ++j)
                        for (int i = j; i < 3; ++i)
                          value[diagonal_entry(outer, k, i, j)] = diagonal(i, j);
                    }
                  });
  if (!defects_.empty()) set_augmented_values();
  strategy_->values_changed();
}

// K's values: M's, the defect rows' s_r·∇_u K_r (Gauss–Newton rows of angle_defect.h) and −1.
void DeformationSystem::set_augmented_values() {
  const AugmentedLayout& A = *layout_.augmented;
  double* value = K_.valuePtr();
  const size_t m_entries = static_cast<size_t>(M_.nonZeros());
  for (size_t e = 0; e < m_entries; ++e) value[A.slot[e]] = M_.valuePtr()[e];
  for (size_t i = 0; i < defects_.star.size(); ++i) {
    if (m_.unknown[static_cast<size_t>(defects_.star[i])] < 0) continue;
    const double s = defects_.weight[static_cast<size_t>(A.entry_row[i])];
    for (size_t j = 0; j < 3; ++j)
      value[A.slot[m_entries + 3 * i + j]] =
          s * linearised_.gradient[i][static_cast<Eigen::Index>(j)];
  }
  const size_t diagonal = m_entries + 3 * defects_.star.size();
  for (size_t r = 0; r < defects_.vertex.size(); ++r) value[A.slot[diagonal + r]] = -1.0;
}

// The defect rows' right-hand side d_r = s_r·(∇K_r·x_ref − K_r) over the free star entries
// (the fixed ones do not move, so their part of ∇K·Δx vanishes).
Eigen::VectorXd DeformationSystem::defect_rhs(const Positions& ref) const {
  Eigen::VectorXd d(static_cast<Eigen::Index>(defects_.vertex.size()));
  for (size_t r = 0; r < defects_.vertex.size(); ++r) {
    double c = -linearised_.defect[r];
    for (int q = defects_.start[r]; q < defects_.start[r + 1]; ++q) {
      const int v = defects_.star[static_cast<size_t>(q)];
      if (m_.unknown[static_cast<size_t>(v)] >= 0)
        c += linearised_.gradient[static_cast<size_t>(q)].dot(ref.row(v).transpose());
    }
    d[static_cast<Eigen::Index>(r)] = defects_.weight[r] * c;
  }
  return d;
}

Eigen::VectorXd DeformationSystem::rhs(const Positions& ref) const {
  const Eigen::Matrix3d L = shape_block();
  Eigen::VectorXd b = Eigen::VectorXd::Zero(3 * static_cast<Eigen::Index>(m_.blocks));
  for (Eigen::Index f = 0; f < g_.solve_faces; ++f) {
    Vec3 x[3];
    for (int c = 0; c < 3; ++c) x[c] = ref.row(g_.F(f, c)).transpose();
    const Vec3 e12 = x[1] - x[0], e13 = x[2] - x[0];   // c of Eq. (13): reference edges
    const Vec3 centroid = (x[0] + x[1] + x[2]) / 3.0;  // and centroid
    const Vec3 atc[3] = {-e12 - e13 + centroid / 3.0, e12 + centroid / 3.0, e13 + centroid / 3.0};
    const Eigen::Matrix3d N =
        w_ * w_ * targets_[static_cast<size_t>(f)] * targets_[static_cast<size_t>(f)].transpose();
    for (int p = 0; p < 3; ++p) {
      const int bp = m_.unknown[static_cast<size_t>(g_.F(f, p))];
      if (bp < 0) continue;
      Vec3 row = atc[p];
      for (int q = 0; q < 3; ++q)  // eliminate the constrained corners (they stay at V0)
        if (m_.unknown[static_cast<size_t>(g_.F(f, q))] < 0)
          row -= corner_block(L, N, p, q) * g_.V0.row(g_.F(f, q)).transpose();
      b.segment<3>(3 * bp) += row;
    }
  }
  const Positions& anchors = moved_anchors_.size() > 0 ? moved_anchors_ : g_.V0;
  for (size_t v = 0; v < m_.unknown.size(); ++v)
    if (m_.unknown[v] >= 0)
      b.segment<3>(3 * m_.unknown[v]) += m_.anchor2[static_cast<size_t>(m_.unknown[v])] *
                                         anchors.row(static_cast<Eigen::Index>(v)).transpose();
  return b;
}

Eigen::VectorXd DeformationSystem::unknowns_of(const Positions& X) const {
  Eigen::VectorXd x(3 * static_cast<Eigen::Index>(m_.blocks));
  for (size_t v = 0; v < m_.unknown.size(); ++v)
    if (m_.unknown[v] >= 0)
      x.segment<3>(3 * m_.unknown[v]) = X.row(static_cast<Eigen::Index>(v)).transpose();
  return x;
}

// With defect rows C, K [x; y] = [b; d] gives (M + CᵀC) x = b + Cᵀd, y = Cx − d.
Eigen::VectorXd DeformationSystem::solve_augmented(const Eigen::VectorXd& b, const Positions& ref) {
  const AugmentedLayout& A = *layout_.augmented;
  Eigen::VectorXd bd(K_.rows());
  const Eigen::VectorXd d = defect_rhs(ref);
  for (size_t m = 0; m < A.place.size(); ++m) bd[A.place[m]] = b[static_cast<Eigen::Index>(m)];
  for (size_t r = 0; r < A.multiplier.size(); ++r)
    bd[A.multiplier[r]] = d[static_cast<Eigen::Index>(r)];
  const Eigen::VectorXd xy = strategy_->solve_quasi_definite(K_, bd);
  Eigen::VectorXd x(b.size());
  for (size_t m = 0; m < A.place.size(); ++m) x[static_cast<Eigen::Index>(m)] = xy[A.place[m]];
  return x;
}

// The frames follow the targets: ν of a vertex is the mean target of its solved faces (the
// face's normal where it has no target, as in a defect patch).
std::vector<Vec3> DeformationSystem::frame_normals() const {
  std::vector<Vec3> normals(static_cast<size_t>(m_.blocks), Vec3::Zero());
  for (Eigen::Index f = 0; f < g_.solve_faces; ++f)
    for (int c = 0; c < 3; ++c) {
      const int k = m_.unknown[static_cast<size_t>(g_.F(f, c))];
      const Vec3& t = targets_[static_cast<size_t>(f)];
      if (k >= 0)
        normals[static_cast<size_t>(k)] +=
            t.isZero() ? face_normal(g_.V0, g_.F, static_cast<int>(f)) : t;
    }
  return normals;
}

Positions DeformationSystem::solve(const Positions& ref) {
  if (m_.blocks == 0) return ref;
  Eigen::VectorXd b;
  {
    StageTimer timer(times_.assembly);
    b = rhs(ref);
  }
  const Eigen::VectorXd x = defects_.empty() ? strategy_->solve(
                                                   M_, b, [&] { return unknowns_of(ref); },
                                                   [this] { return frame_normals(); })
                                             : solve_augmented(b, ref);
  ++times_.solves;
  times_.factorizations = strategy_->factorizations();
  times_.factorization_flops = strategy_->factorization_flops();
  times_.substituted = strategy_->substituted() ? 1 : 0;
  Positions out = ref;
  for (size_t v = 0; v < m_.unknown.size(); ++v)
    if (m_.unknown[v] >= 0)
      out.row(static_cast<Eigen::Index>(v)) = x.segment<3>(3 * m_.unknown[v]).transpose();
  return out;
}

}  // namespace qd::approximate
