// One piece from patch to flat: cut to a disk (cut_to_disk.h), initial layout with the boundary
// first (initial_layout.h), ARAP (arap.h) from there, and its measures (piece_measures.h).
#pragma once

#include <functional>
#include <vector>

#include "flatten/arap.h"
#include "flatten/cut_to_disk.h"
#include "flatten/flatten_problem.h"
#include "flatten/piece.h"
#include "flatten/piece_measures.h"

namespace qd::flatten {

struct FlatPiece {
  Piece piece;                          // as cut
  Eigen::MatrixX2d uv;                  // per vertex of the cut piece, model units
  std::vector<std::vector<int>> loops;  // its boundary (one loop: it is a disk)
  DiskCut cut;
  ArapOutcome arap;
  PieceMeasures measures;
  double time_ms = 0;
};

// iteration(k) is called after ARAP iteration k. Throws qd::common::Error if a system is singular.
FlatPiece flatten_piece(Piece piece, const FlattenParams& params,
                        const std::function<void(int iteration)>& iteration = {});

}  // namespace qd::flatten
