// The pattern as it is cut: one pattern piece per group of congruent or mirror-image pieces
// (symmetric_pieces.h), marked with how many to cut and how many of them turned over, and the
// pieces laid out anew by their cut lines' boxes in shelves (shelf_pack, layout.h). The
// flattened mesh keeps every piece; only the pattern files show one per group.
#pragma once

#include <vector>

#include "flatten/pattern.h"
#include "flatten/symmetric_pieces.h"

namespace qd::flatten {

// pieces: every pattern piece, grain along +y; groups: a partition of them (representative
// first); gap > 0: the space between cut lines on the sheet.
Pattern pattern_sheet(std::vector<PatternPiece> pieces, const std::vector<PieceGroup>& groups,
                      double gap);

}  // namespace qd::flatten
