// A flattened piece's figures as the adapters report them (flatten_result.h), and its log line.
#pragma once

#include <string>

#include "flatten/flatten_piece.h"
#include "flatten/flatten_result.h"

namespace qd::flatten {

// flat: the piece; label: as on the pattern; box: where the layout put it.
PieceReport piece_report(const FlatPiece& flat, const std::string& label,
                         const Eigen::AlignedBox2d& box);

// "patch 3: 1200 faces, cut …; 12 ARAP iterations (converged); length distortion max …", ending
// in "not flattenable without a cut" when the piece has flipped or overlapping faces.
std::string log_line(const PieceReport& r);

}  // namespace qd::flatten
