#include "approximate/deformation_system.h"

#include <Eigen/Dense>
#include <algorithm>

#include "approximate/anchor_weights.h"
#include "approximate/common_names.h"
#include "common/parallel_for.h"
#include "common/stage_timer.h"
#include "common/vertex_order.h"

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

constexpr int kPairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};

}  // namespace

DeformationSystem::DeformationSystem(const GroupMesh& group, const Params& params, double ae,
                                     const std::vector<char>& defect_rows)
    : g_(group),
      w_(params.weight),
      incident_(group.F, group.V0.rows()),
      defects_(defect_rows.empty()
                   ? DefectStars{}
                   : defect_stars(g_, incident_, defect_rows, params.defect_weight)),
      threads_(params.threads) {
  const size_t n = g_.fixed.size();
  std::vector<int> free_index(n, -1);
  int free_count = 0;
  for (size_t v = 0; v < n; ++v)
    if (!g_.fixed[v]) free_index[v] = free_count++;
  std::vector<std::pair<int, int>> edges;
  for (Eigen::Index f = 0; f < g_.solve_faces; ++f)
    for (const auto& pq : kPairs) {
      const int a = free_index[static_cast<size_t>(g_.F(f, pq[0]))];
      const int b = free_index[static_cast<size_t>(g_.F(f, pq[1]))];
      if (a >= 0 && b >= 0) edges.emplace_back(a, b);
    }
  const std::vector<int> rank = fill_reducing_rank(free_count, edges);
  unknown_.assign(n, -1);
  block_vertex_.resize(static_cast<size_t>(free_count));
  for (size_t v = 0; v < n; ++v)
    if (free_index[v] >= 0) {
      unknown_[v] = rank[static_cast<size_t>(free_index[v])];
      block_vertex_[static_cast<size_t>(unknown_[v])] = static_cast<int>(v);
    }
  blocks_ = free_count;
  strategy_.emplace(params, 3L * blocks_, !defects_.empty(), pattern_, times_);
  const std::vector<double> mls = mls_weights(g_.V0, g_.fixed, ae, threads_);
  anchor2_.resize(static_cast<size_t>(blocks_));
  for (size_t v = 0; v < n; ++v)
    if (unknown_[v] >= 0)
      anchor2_[static_cast<size_t>(unknown_[v])] = params.anchor * params.anchor * mls[v] * mls[v];
  for (auto& edge : edges)  // now in unknown-block numbering
    edge = {rank[static_cast<size_t>(edge.first)], rank[static_cast<size_t>(edge.second)]};
  build_pattern(edges);
  if (!defects_.empty()) build_augmented_pattern();
}

// The lower-triangle pattern of M from the block edges (unknown block pairs of the faces): per
// block column k, the diagonal block (lower part) then each neighbouring block row r > k;
// column 3k+j holds rows 3k+j..3k+2, then 3r..3r+2 per r.
void DeformationSystem::build_pattern(const std::vector<std::pair<int, int>>& edges) {
  pattern_ = lower_pattern(blocks_, edges);

  face_slot_.assign(static_cast<size_t>(g_.solve_faces) * 3, -1);
  for (Eigen::Index f = 0; f < g_.solve_faces; ++f)
    for (int e = 0; e < 3; ++e) {
      const int a = unknown_[static_cast<size_t>(g_.F(f, kPairs[e][0]))];
      const int b = unknown_[static_cast<size_t>(g_.F(f, kPairs[e][1]))];
      if (a < 0 || b < 0 || a == b) continue;
      const auto rows = pattern_.block_row.begin();
      face_slot_[static_cast<size_t>(3 * f + e)] =
          static_cast<int>(std::lower_bound(rows + pattern_.begin(std::min(a, b)),
                                            rows + pattern_.end(std::min(a, b)), std::max(a, b)) -
                           rows);
    }

  const Eigen::Index size = 3 * static_cast<Eigen::Index>(blocks_);
  M_.resize(size, size);
  M_.resizeNonZeros(6 * blocks_ + 9 * static_cast<Eigen::Index>(pattern_.block_row.size()));
  int* outer = M_.outerIndexPtr();
  int* inner = M_.innerIndexPtr();
  int at = 0;
  for (int k = 0; k < blocks_; ++k)
    for (int j = 0; j < 3; ++j) {
      outer[3 * k + j] = at;
      for (int i = j; i < 3; ++i) inner[at++] = 3 * k + i;
      for (int s = pattern_.begin(k); s < pattern_.end(k); ++s)
        for (int i = 0; i < 3; ++i) inner[at++] = 3 * pattern_.row(s) + i;
    }
  outer[size] = at;
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
  parallel_ranges(static_cast<size_t>(blocks_), static_cast<size_t>(threads_), kRangeChunk,
                  [&](size_t first, size_t last) {
                    for (int k = static_cast<int>(first); k < static_cast<int>(last); ++k) {
                      std::fill(value + outer[3 * k], value + outer[3 * k + 3], 0.0);
                      Eigen::Matrix3d diagonal =
                          anchor2_[static_cast<size_t>(k)] * Eigen::Matrix3d::Identity();
                      const int v = block_vertex_[static_cast<size_t>(k)];
                      for (int c = incident_.start[static_cast<size_t>(v)];
                           c < incident_.start[static_cast<size_t>(v) + 1]; ++c) {
                        const int f = incident_.faces[static_cast<size_t>(c)];
                        if (f >= g_.solve_faces) continue;  // a ring face: measured, not solved
                        const int p = g_.F(f, 0) == v ? 0 : g_.F(f, 1) == v ? 1 : 2;
                        const Vec3& n = targets_[static_cast<size_t>(f)];
                        const Eigen::Matrix3d N = w_ * w_ * n * n.transpose();
                        diagonal += corner_block(L, N, p, p);
                        for (int e = 0; e < 3; ++e) {
                          const int a = kPairs[e][0], b = kPairs[e][1];
                          const int s = face_slot_[static_cast<size_t>(3 * f + e)];
                          if (s < 0 || (a != p && b != p)) continue;
                          const int other = unknown_[static_cast<size_t>(g_.F(f, a == p ? b : a))];
                          if (other < k)
                            continue;  // that block belongs to the other vertex's column
                          const Eigen::Matrix3d B = corner_block(L, N, a, b);  // symmetric
                          for (int j = 0; j < 3; ++j)
                            for (int i = 0; i < 3; ++i)
                              value[block_entry(outer, pattern_, k, s, i, j)] += B(i, j);
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

// K's unknowns follow M's fill-reducing block order, each row's multiplier right after its
// vertex's three coordinates. With a vertex's unknowns merged, K's graph is the vertex graph M
// was ordered on (a row couples its vertex's star), so K needs no order of its own (the
// alternatives measured: docs/solvers.md). The pattern is built once by Eigen from the entries'
// places, each entry's value being its source's number, which then tells where each source goes.
void DeformationSystem::build_augmented_pattern() {
  const size_t rows = defects_.vertex.size(), blocks = static_cast<size_t>(blocks_);
  entry_row_.resize(defects_.star.size());
  for (size_t r = 0; r < rows; ++r)
    std::fill(entry_row_.begin() + defects_.start[r], entry_row_.begin() + defects_.start[r + 1],
              static_cast<int>(r));
  std::vector<int> block_row(blocks, -1);
  for (size_t r = 0; r < rows; ++r) {
    const int k = unknown_[static_cast<size_t>(defects_.vertex[r])];
    if (k >= 0) block_row[static_cast<size_t>(k)] = static_cast<int>(r);
  }
  std::vector<int> first(blocks + 1, 0);  // K's first unknown of each block
  for (size_t k = 0; k < blocks; ++k) first[k + 1] = first[k] + 3 + (block_row[k] >= 0 ? 1 : 0);
  multiplier_.assign(rows, -1);
  int extra = first[blocks];  // a row whose vertex is fixed (none today) comes last
  for (size_t r = 0; r < rows; ++r) {
    const int k = unknown_[static_cast<size_t>(defects_.vertex[r])];
    multiplier_[r] = k >= 0 ? first[static_cast<size_t>(k)] + 3 : extra++;
  }
  place_.resize(3 * blocks);
  for (size_t m = 0; m < place_.size(); ++m) place_[m] = first[m / 3] + static_cast<int>(m % 3);
  const auto place = [&](int m) { return place_[static_cast<size_t>(m)]; };

  std::vector<Eigen::Triplet<double>> entries;  // value: 1 + the source's number
  const auto add = [&](int a, int b, size_t source) {
    entries.emplace_back(std::max(a, b), std::min(a, b), static_cast<double>(source + 1));
  };
  const size_t m_entries = static_cast<size_t>(M_.nonZeros());
  for (int c = 0; c < M_.cols(); ++c)
    for (int e = M_.outerIndexPtr()[c]; e < M_.outerIndexPtr()[c + 1]; ++e)
      add(place(M_.innerIndexPtr()[e]), place(c), static_cast<size_t>(e));
  for (size_t i = 0; i < defects_.star.size(); ++i) {
    const int k = unknown_[static_cast<size_t>(defects_.star[i])];
    if (k < 0) continue;
    for (int j = 0; j < 3; ++j)
      add(first[static_cast<size_t>(k)] + j, multiplier_[static_cast<size_t>(entry_row_[i])],
          m_entries + 3 * i + static_cast<size_t>(j));
  }
  const size_t diagonal = m_entries + 3 * defects_.star.size();
  for (size_t r = 0; r < rows; ++r) add(multiplier_[r], multiplier_[r], diagonal + r);
  K_.resize(extra, extra);
  K_.setFromTriplets(entries.begin(), entries.end());
  slot_.assign(diagonal + rows, -1);
  for (Eigen::Index e = 0; e < K_.nonZeros(); ++e)
    slot_[static_cast<size_t>(K_.valuePtr()[e]) - 1] = static_cast<int>(e);
}

// K's values: M's, the defect rows' s_r·∇_u K_r (Gauss–Newton rows of angle_defect.h) and −1.
void DeformationSystem::set_augmented_values() {
  double* value = K_.valuePtr();
  const size_t m_entries = static_cast<size_t>(M_.nonZeros());
  for (size_t e = 0; e < m_entries; ++e) value[slot_[e]] = M_.valuePtr()[e];
  for (size_t i = 0; i < defects_.star.size(); ++i) {
    if (unknown_[static_cast<size_t>(defects_.star[i])] < 0) continue;
    const double s = defects_.weight[static_cast<size_t>(entry_row_[i])];
    for (size_t j = 0; j < 3; ++j)
      value[slot_[m_entries + 3 * i + j]] =
          s * linearised_.gradient[i][static_cast<Eigen::Index>(j)];
  }
  const size_t diagonal = m_entries + 3 * defects_.star.size();
  for (size_t r = 0; r < defects_.vertex.size(); ++r) value[slot_[diagonal + r]] = -1.0;
}

// The defect rows' right-hand side d_r = s_r·(∇K_r·x_ref − K_r) over the free star entries
// (the fixed ones do not move, so their part of ∇K·Δx vanishes).
Eigen::VectorXd DeformationSystem::defect_rhs(const Positions& ref) const {
  Eigen::VectorXd d(static_cast<Eigen::Index>(defects_.vertex.size()));
  for (size_t r = 0; r < defects_.vertex.size(); ++r) {
    double c = -linearised_.defect[r];
    for (int q = defects_.start[r]; q < defects_.start[r + 1]; ++q) {
      const int v = defects_.star[static_cast<size_t>(q)];
      if (unknown_[static_cast<size_t>(v)] >= 0)
        c += linearised_.gradient[static_cast<size_t>(q)].dot(ref.row(v).transpose());
    }
    d[static_cast<Eigen::Index>(r)] = defects_.weight[r] * c;
  }
  return d;
}

Eigen::VectorXd DeformationSystem::rhs(const Positions& ref) const {
  const Eigen::Matrix3d L = shape_block();
  Eigen::VectorXd b = Eigen::VectorXd::Zero(3 * static_cast<Eigen::Index>(blocks_));
  for (Eigen::Index f = 0; f < g_.solve_faces; ++f) {
    Vec3 x[3];
    for (int c = 0; c < 3; ++c) x[c] = ref.row(g_.F(f, c)).transpose();
    const Vec3 e12 = x[1] - x[0], e13 = x[2] - x[0];   // c of Eq. (13): reference edges
    const Vec3 centroid = (x[0] + x[1] + x[2]) / 3.0;  // and centroid
    const Vec3 atc[3] = {-e12 - e13 + centroid / 3.0, e12 + centroid / 3.0, e13 + centroid / 3.0};
    const Eigen::Matrix3d N =
        w_ * w_ * targets_[static_cast<size_t>(f)] * targets_[static_cast<size_t>(f)].transpose();
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
      b.segment<3>(3 * unknown_[v]) += anchor2_[static_cast<size_t>(unknown_[v])] *
                                       g_.V0.row(static_cast<Eigen::Index>(v)).transpose();
  return b;
}

Eigen::VectorXd DeformationSystem::unknowns_of(const Positions& X) const {
  Eigen::VectorXd x(3 * static_cast<Eigen::Index>(blocks_));
  for (size_t v = 0; v < unknown_.size(); ++v)
    if (unknown_[v] >= 0)
      x.segment<3>(3 * unknown_[v]) = X.row(static_cast<Eigen::Index>(v)).transpose();
  return x;
}

// With defect rows C, K [x; y] = [b; d] gives (M + CᵀC) x = b + Cᵀd, y = Cx − d.
Eigen::VectorXd DeformationSystem::solve_augmented(const Eigen::VectorXd& b, const Positions& ref) {
  Eigen::VectorXd bd(K_.rows());
  const Eigen::VectorXd d = defect_rhs(ref);
  for (size_t m = 0; m < place_.size(); ++m) bd[place_[m]] = b[static_cast<Eigen::Index>(m)];
  for (size_t r = 0; r < multiplier_.size(); ++r)
    bd[multiplier_[r]] = d[static_cast<Eigen::Index>(r)];
  const Eigen::VectorXd xy = strategy_->solve_quasi_definite(K_, bd);
  Eigen::VectorXd x(b.size());
  for (size_t m = 0; m < place_.size(); ++m) x[static_cast<Eigen::Index>(m)] = xy[place_[m]];
  return x;
}

// The frames follow the targets: ν of a vertex is the mean target of its solved faces (the
// face's normal where it has no target, as in a defect patch).
std::vector<Vec3> DeformationSystem::frame_normals() const {
  std::vector<Vec3> normals(static_cast<size_t>(blocks_), Vec3::Zero());
  for (Eigen::Index f = 0; f < g_.solve_faces; ++f)
    for (int c = 0; c < 3; ++c) {
      const int k = unknown_[static_cast<size_t>(g_.F(f, c))];
      const Vec3& t = targets_[static_cast<size_t>(f)];
      if (k >= 0)
        normals[static_cast<size_t>(k)] +=
            t.isZero() ? face_normal(g_.V0, g_.F, static_cast<int>(f)) : t;
    }
  return normals;
}

Positions DeformationSystem::solve(const Positions& ref) {
  if (blocks_ == 0) return ref;
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
  times_.substituted = strategy_->substituted() ? 1 : 0;
  Positions out = ref;
  for (size_t v = 0; v < unknown_.size(); ++v)
    if (unknown_[v] >= 0)
      out.row(static_cast<Eigen::Index>(v)) = x.segment<3>(3 * unknown_[v]).transpose();
  return out;
}

}  // namespace qd::approximate
