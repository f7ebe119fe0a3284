#include "flatten/cotangent_laplacian.h"

#include <cassert>

namespace qd::flatten {

Eigen::SparseMatrix<double> cotangent_laplacian(const Triangles& F, const FlatTriangles& g,
                                                int vertex_count) {
  assert(g.half_cot.rows() == F.rows());
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(12 * static_cast<size_t>(F.rows()));
  for (int f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int i = F(f, (k + 1) % 3), j = F(f, (k + 2) % 3);
      const double w = g.half_cot(f, k);
      entries.emplace_back(i, j, -w);
      entries.emplace_back(j, i, -w);
      entries.emplace_back(i, i, w);
      entries.emplace_back(j, j, w);
    }
  Eigen::SparseMatrix<double> L(vertex_count, vertex_count);
  L.setFromTriplets(entries.begin(), entries.end());
  return L;
}

Eigen::SparseMatrix<double> sparse_block(const Eigen::SparseMatrix<double>& M,
                                         const std::vector<int>& row, int rows,
                                         const std::vector<int>& column, int columns) {
  assert(row.size() == static_cast<size_t>(M.rows()) &&
         column.size() == static_cast<size_t>(M.cols()));
  std::vector<Eigen::Triplet<double>> entries;
  for (int c = 0; c < M.outerSize(); ++c) {
    if (column[c] < 0) continue;
    for (Eigen::SparseMatrix<double>::InnerIterator it(M, c); it; ++it)
      if (row[it.row()] >= 0) entries.emplace_back(row[it.row()], column[c], it.value());
  }
  Eigen::SparseMatrix<double> block(rows, columns);
  block.setFromTriplets(entries.begin(), entries.end());
  return block;
}

}  // namespace qd::flatten
