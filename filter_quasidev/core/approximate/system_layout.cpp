#include "approximate/system_layout.h"

#include <algorithm>

#include "approximate/anchor_weights.h"
#include "approximate/solve_strategy.h"
#include "common/vertex_order.h"

namespace qd::approximate {

MatrixLayout::MatrixLayout(const GroupMesh& g, const Params& params, double ae,
                           common::FillOrder order)
    : incident(g.F, g.V0.rows()) {
  const size_t n = g.fixed.size();
  std::vector<int> free_index(n, -1);
  int free_count = 0;
  for (size_t v = 0; v < n; ++v)
    if (!g.fixed[v]) free_index[v] = free_count++;
  std::vector<std::pair<int, int>> edges;
  for (Eigen::Index f = 0; f < g.solve_faces; ++f)
    for (const auto& pq : kCornerPairs) {
      const int a = free_index[static_cast<size_t>(g.F(f, pq[0]))];
      const int b = free_index[static_cast<size_t>(g.F(f, pq[1]))];
      if (a >= 0 && b >= 0) edges.emplace_back(a, b);
    }
  std::vector<Vec3> points;
  if (order == common::FillOrder::Coordinates)
    for (size_t v = 0; v < n; ++v)
      if (free_index[v] >= 0) points.push_back(g.V0.row(static_cast<Eigen::Index>(v)).transpose());
  const std::vector<int> rank =
      order == common::FillOrder::Coordinates
          ? common::fill_reducing_rank(common::lower_pattern(free_count, edges), points,
                                       kLeastFillFromBlocks, params.threads)
          : common::fill_reducing_rank(free_count, edges, order);
  unknown.assign(n, -1);
  block_vertex.resize(static_cast<size_t>(free_count));
  for (size_t v = 0; v < n; ++v)
    if (free_index[v] >= 0) {
      unknown[v] = rank[static_cast<size_t>(free_index[v])];
      block_vertex[static_cast<size_t>(unknown[v])] = static_cast<int>(v);
    }
  blocks = free_count;
  const std::vector<double> mls = mls_weights(g.V0, g.fixed, ae, params.threads);
  anchor2.resize(static_cast<size_t>(blocks));
  for (size_t v = 0; v < n; ++v)
    if (unknown[v] >= 0)
      anchor2[static_cast<size_t>(unknown[v])] = params.anchor * params.anchor * mls[v] * mls[v];
  for (auto& edge : edges)  // now in unknown-block numbering
    edge = {rank[static_cast<size_t>(edge.first)], rank[static_cast<size_t>(edge.second)]};
  build_pattern(g, edges);
}

// The lower-triangle pattern of M from the block edges (unknown block pairs of the faces): per
// block column k, the diagonal block (lower part) then each neighbouring block row r > k;
// column 3k+j holds rows 3k+j..3k+2, then 3r..3r+2 per r.
void MatrixLayout::build_pattern(const GroupMesh& g,
                                 const std::vector<std::pair<int, int>>& edges) {
  pattern = lower_pattern(blocks, edges);

  face_slot.assign(static_cast<size_t>(g.solve_faces) * 3, -1);
  for (Eigen::Index f = 0; f < g.solve_faces; ++f)
    for (int e = 0; e < 3; ++e) {
      const int a = unknown[static_cast<size_t>(g.F(f, kCornerPairs[e][0]))];
      const int b = unknown[static_cast<size_t>(g.F(f, kCornerPairs[e][1]))];
      if (a < 0 || b < 0 || a == b) continue;
      const auto rows = pattern.block_row.begin();
      face_slot[static_cast<size_t>(3 * f + e)] =
          static_cast<int>(std::lower_bound(rows + pattern.begin(std::min(a, b)),
                                            rows + pattern.end(std::min(a, b)), std::max(a, b)) -
                           rows);
    }

  const Eigen::Index size = 3 * static_cast<Eigen::Index>(blocks);
  M.resize(size, size);
  M.resizeNonZeros(6 * blocks + 9 * static_cast<Eigen::Index>(pattern.block_row.size()));
  int* outer = M.outerIndexPtr();
  int* inner = M.innerIndexPtr();
  int at = 0;
  for (int k = 0; k < blocks; ++k)
    for (int j = 0; j < 3; ++j) {
      outer[3 * k + j] = at;
      for (int i = j; i < 3; ++i) inner[at++] = 3 * k + i;
      for (int s = pattern.begin(k); s < pattern.end(k); ++s)
        for (int i = 0; i < 3; ++i) inner[at++] = 3 * pattern.row(s) + i;
    }
  outer[size] = at;
  std::fill(M.valuePtr(), M.valuePtr() + at, 0.0);
}

// With a vertex's unknowns merged, K's graph is the vertex graph M was ordered on (a row couples
// its vertex's star), so K needs no order of its own (the alternatives measured:
// docs/solvers.md). The pattern is built once by Eigen from the entries' places, each entry's
// value being its source's number, which then tells where each source goes.
AugmentedLayout::AugmentedLayout(const MatrixLayout& m, DefectStars stars)
    : defects(std::move(stars)) {
  const size_t rows = defects.vertex.size(), blocks = static_cast<size_t>(m.blocks);
  entry_row.resize(defects.star.size());
  for (size_t r = 0; r < rows; ++r)
    std::fill(entry_row.begin() + defects.start[r], entry_row.begin() + defects.start[r + 1],
              static_cast<int>(r));
  std::vector<int> block_row(blocks, -1);
  for (size_t r = 0; r < rows; ++r) {
    const int k = m.unknown[static_cast<size_t>(defects.vertex[r])];
    if (k >= 0) block_row[static_cast<size_t>(k)] = static_cast<int>(r);
  }
  std::vector<int> first(blocks + 1, 0);  // K's first unknown of each block
  for (size_t k = 0; k < blocks; ++k) first[k + 1] = first[k] + 3 + (block_row[k] >= 0 ? 1 : 0);
  multiplier.assign(rows, -1);
  int extra = first[blocks];  // a row whose vertex is fixed (none today) comes last
  for (size_t r = 0; r < rows; ++r) {
    const int k = m.unknown[static_cast<size_t>(defects.vertex[r])];
    multiplier[r] = k >= 0 ? first[static_cast<size_t>(k)] + 3 : extra++;
  }
  place.resize(3 * blocks);
  for (size_t u = 0; u < place.size(); ++u) place[u] = first[u / 3] + static_cast<int>(u % 3);
  const auto place_of = [&](int u) { return place[static_cast<size_t>(u)]; };

  std::vector<Eigen::Triplet<double>> entries;  // value: 1 + the source's number
  const auto add = [&](int a, int b, size_t source) {
    entries.emplace_back(std::max(a, b), std::min(a, b), static_cast<double>(source + 1));
  };
  const size_t m_entries = static_cast<size_t>(m.M.nonZeros());
  for (int c = 0; c < m.M.cols(); ++c)
    for (int e = m.M.outerIndexPtr()[c]; e < m.M.outerIndexPtr()[c + 1]; ++e)
      add(place_of(m.M.innerIndexPtr()[e]), place_of(c), static_cast<size_t>(e));
  for (size_t i = 0; i < defects.star.size(); ++i) {
    const int k = m.unknown[static_cast<size_t>(defects.star[i])];
    if (k < 0) continue;
    for (int j = 0; j < 3; ++j)
      add(first[static_cast<size_t>(k)] + j, multiplier[static_cast<size_t>(entry_row[i])],
          m_entries + 3 * i + static_cast<size_t>(j));
  }
  const size_t diagonal = m_entries + 3 * defects.star.size();
  for (size_t r = 0; r < rows; ++r) add(multiplier[r], multiplier[r], diagonal + r);
  K.resize(extra, extra);
  K.setFromTriplets(entries.begin(), entries.end());
  slot.assign(diagonal + rows, -1);
  for (Eigen::Index e = 0; e < K.nonZeros(); ++e)
    slot[static_cast<size_t>(K.valuePtr()[e]) - 1] = static_cast<int>(e);
}

SystemLayouts::SystemLayouts(const GroupMesh& g, const Params& params, double ae)
    : g_(g), params_(params), ae_(ae) {}

std::shared_ptr<const MatrixLayout> SystemLayouts::matrix(bool defect_rows) {
  const auto free = std::count(g_.fixed.begin(), g_.fixed.end(), false);
  if (defect_rows && free >= kLeastFillFromBlocks) {
    if (!defect_matrix_)
      defect_matrix_ =
          std::make_shared<const MatrixLayout>(g_, params_, ae_, common::FillOrder::LeastFill);
    return defect_matrix_;
  }
  if (!matrix_)
    matrix_ = std::make_shared<const MatrixLayout>(g_, params_, ae_,
                                                   free >= kLeastFillFromBlocks
                                                       ? common::FillOrder::Coordinates
                                                       : common::FillOrder::MinimumDegree);
  return matrix_;
}

SystemLayout SystemLayouts::get(const std::vector<char>& defect_rows) {
  const auto known = layouts_.find(defect_rows);
  if (known != layouts_.end()) return known->second;
  SystemLayout layout;
  if (!defect_rows.empty()) {
    const std::shared_ptr<const MatrixLayout> with_rows = matrix(true);
    DefectStars stars = defect_stars(g_, with_rows->incident, defect_rows, params_.defect_weight);
    if (!stars.empty())
      layout = {with_rows, std::make_shared<const AugmentedLayout>(*with_rows, std::move(stars))};
  }
  if (!layout.matrix) layout.matrix = matrix(false);
  layouts_.emplace(defect_rows, layout);
  return layout;
}

}  // namespace qd::approximate
