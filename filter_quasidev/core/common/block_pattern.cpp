#include "common/block_pattern.h"

#include <algorithm>

namespace qd::common {

BlockPattern lower_pattern(int nodes, const std::vector<std::pair<int, int>>& edges) {
  std::vector<int> start(static_cast<size_t>(nodes) + 1, 0);
  for (const auto& [a, b] : edges)
    if (a != b) ++start[static_cast<size_t>(std::min(a, b)) + 1];
  for (size_t c = 0; c < static_cast<size_t>(nodes); ++c) start[c + 1] += start[c];
  std::vector<int> row(static_cast<size_t>(start.back()));
  std::vector<int> next(start.begin(), start.end() - 1);
  for (const auto& [a, b] : edges)
    if (a != b)
      row[static_cast<size_t>(next[static_cast<size_t>(std::min(a, b))]++)] = std::max(a, b);
  BlockPattern p;  // each column sorted and without repeats, compacted in place
  p.column_start.assign(static_cast<size_t>(nodes) + 1, 0);
  size_t kept = 0;
  for (size_t c = 0; c < static_cast<size_t>(nodes); ++c) {
    const auto first = row.begin() + start[c], last = row.begin() + start[c + 1];
    std::sort(first, last);
    const auto end = std::unique(first, last);
    for (auto r = first; r != end; ++r) row[kept++] = *r;
    p.column_start[c + 1] = static_cast<int>(kept);
  }
  row.resize(kept);
  p.block_row = std::move(row);
  return p;
}

Eigen::SparseMatrix<double> scalar_lower(const BlockPattern& p) {
  const int n = p.blocks();
  const int entries = n + static_cast<int>(p.block_row.size());
  Eigen::SparseMatrix<double> K(n, n);
  K.resizeNonZeros(entries);
  int* outer = K.outerIndexPtr();
  int* inner = K.innerIndexPtr();
  for (int k = 0; k < n; ++k) {
    outer[k] = k + p.begin(k);
    inner[outer[k]] = k;
    for (int s = p.begin(k); s < p.end(k); ++s) inner[outer[k] + 1 + s - p.begin(k)] = p.row(s);
  }
  outer[n] = entries;
  std::fill(K.valuePtr(), K.valuePtr() + entries, 0.0);
  return K;
}

}  // namespace qd::common
