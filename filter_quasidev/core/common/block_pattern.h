// The sparsity of the coupled normal matrix M (Eq. 17) in 3×3 vertex blocks: its lower triangle
// holds, per block column k, the diagonal block (lower part) and the off-diagonal blocks of the
// neighbouring block rows r > k. Column 3k+j stores rows 3k+j..3k+2, then 3r..3r+2 per r, so an
// entry's place in M's values follows from the block's slot alone.
#pragma once

#include <Eigen/SparseCore>
#include <cstddef>
#include <utility>
#include <vector>

namespace qd::common {

struct BlockPattern {
  std::vector<int> column_start;  // off-diagonal blocks of block column k: [start[k], start[k+1])
  std::vector<int> block_row;     // their block rows, ascending in each column

  int blocks() const { return static_cast<int>(column_start.size()) - 1; }
  int begin(int k) const { return column_start[static_cast<size_t>(k)]; }
  int end(int k) const { return column_start[static_cast<size_t>(k) + 1]; }
  int row(int s) const { return block_row[static_cast<size_t>(s)]; }
};

// The pattern of a graph with `nodes` nodes and the given edges (either orientation, repeats
// and self loops allowed): per node c its neighbours r > c. Counting sort, O(nodes + edges).
BlockPattern lower_pattern(int nodes, const std::vector<std::pair<int, int>>& edges);

// The n×n lower-triangular matrix of the pattern, diagonal included (per column: the diagonal,
// then the neighbours below it), every value 0.
Eigen::SparseMatrix<double> scalar_lower(const BlockPattern& p);

// Offset of entry (i, j), i ≥ j, of the diagonal block in column 3k+j of M's values.
inline int diagonal_entry(const int* outer, int k, int i, int j) {
  return outer[3 * k + j] + (i - j);
}

// Offset of entry (i, j) of the off-diagonal block in slot s (of block column k) in M's values.
inline int block_entry(const int* outer, const BlockPattern& p, int k, int s, int i, int j) {
  return outer[3 * k + j] + (3 - j) + 3 * (s - p.begin(k)) + i;
}

}  // namespace qd::common
