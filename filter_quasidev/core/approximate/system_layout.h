// What a group's deformation system (deformation_system.h) takes from the group and from which
// vertices get angle-defect rows, and not from the targets or the weights: the fill-reducing
// order of the unknowns, M's and K's sparsity patterns, the anchor weights of Eq. (15) and K's
// symbolic analysis. The candidates of a race (term_race.h) differ in targets and defect rows
// only, so SystemLayouts computes each of these once per group and pattern and the candidates
// share them; the same order and analysis give the same factor, bit for bit.
#pragma once

#include <Eigen/SparseCore>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "approximate/angle_defect.h"
#include "approximate/common_names.h"
#include "approximate/group_mesh.h"
#include "approximate/params.h"
#include "common/block_pattern.h"
#include "common/quasi_definite_factor.h"
#include "common/vertex_order.h"

namespace qd::approximate {

// A face's corner pairs, in the order of MatrixLayout::face_slot.
constexpr int kCornerPairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};

// M's unknowns and pattern: unknown 3k+d is coordinate d of block k; blocks follow a
// fill-reducing order of the free vertices' graph (vertex_order.h).
struct MatrixLayout {
  // ae: the average edge length of Eq. (15); order: how the free vertices are ordered.
  MatrixLayout(const GroupMesh& g, const Params& params, double ae, common::FillOrder order);

  VertexFaces incident;           // faces of each local vertex, ascending
  std::vector<int> unknown;       // unknown block of each local vertex (-1 when fixed)
  std::vector<int> block_vertex;  // local vertex of each unknown block
  int blocks = 0;
  std::vector<double> anchor2;    // α²·w(v)² per unknown block
  BlockPattern pattern;           // M's blocks
  std::vector<int> face_slot;     // per face and corner pair (0,1),(0,2),(1,2): off-diag block
  Eigen::SparseMatrix<double> M;  // M's lower triangle, values 0

 private:
  void build_pattern(const GroupMesh& g, const std::vector<std::pair<int, int>>& edges);
};

// K = [[M, Cᵀ], [C, −I]] for one set of defect rows (deformation_system.h): K's unknowns
// follow M's block order, each row's multiplier right after its vertex's three coordinates.
struct AugmentedLayout {
  // defects: the rows (defect_stars, not empty).
  AugmentedLayout(const MatrixLayout& m, DefectStars defects);

  DefectStars defects;            // the rows, at their unscaled weights
  std::vector<int> entry_row;     // row of each defect star entry
  std::vector<int> place;         // K's unknown of each unknown of M
  std::vector<int> multiplier;    // K's unknown of each defect row's multiplier
  std::vector<int> slot;          // place in K's values of each source
  Eigen::SparseMatrix<double> K;  // K's lower triangle (values: scratch)
  std::shared_ptr<SharedAnalysis> analysis = std::make_shared<SharedAnalysis>();  // K's
};

// One system's layouts; augmented is null without defect rows.
struct SystemLayout {
  std::shared_ptr<const MatrixLayout> matrix;
  std::shared_ptr<const AugmentedLayout> augmented;
};

// The layouts of one group, each computed at its first request. From kLeastFillFromBlocks free
// vertices (solve_strategy.h) the systems with defect rows, always factorised, take an M
// ordered by common::FillOrder::LeastFill, and those without, which conjugate gradients solve,
// one ordered by common::FillOrder::Coordinates (cut into parts of at most kLeastFillFromBlocks
// vertices): it costs a fraction of METIS's order, and their preconditioner's factors are read
// in every CG iteration.
class SystemLayouts {
 public:
  // params: α (Eq. 15), w_d (a system at another w_d weighs the rows again) and the threads;
  // ae: the average edge length.
  SystemLayouts(const GroupMesh& g, const Params& params, double ae);
  // The layout for these defect rows (per local vertex, 1 = a row; empty = none).
  SystemLayout get(const std::vector<char>& defect_rows);

 private:
  // M's layout for systems with or without defect rows.
  std::shared_ptr<const MatrixLayout> matrix(bool defect_rows);

  const GroupMesh& g_;
  Params params_;
  double ae_;
  std::shared_ptr<const MatrixLayout> matrix_;         // of the systems without defect rows
  std::shared_ptr<const MatrixLayout> defect_matrix_;  // of those with (the same below the bound)
  std::map<std::vector<char>, SystemLayout> layouts_;
};

}  // namespace qd::approximate
