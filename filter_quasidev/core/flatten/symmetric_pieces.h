// Symmetric pieces (issue 26): pattern pieces that are congruent, or mirror images of each other,
// within a tolerance are cut from one piece N times, turned over where needed.
//
// Method. The pieces share an orientation on the sheet (grain along +y, or the layout's principal
// axis along x), so a piece can only match another turned by one of the four symmetries of that
// frame: identity, 180° rotation, mirror x → −x (a left/right pair), mirror y → −y. Two pieces with
// a different number of boundary loops never match; two whose areas differ by more than the
// tolerance band around the boundary can hold (2·tolerance·perimeter) are rejected unaligned.
// Otherwise, for each symmetry, area centroid is moved onto area centroid and the fit is refined by
// iterative closest points (Besl & McKay 1992) with the 2D Procrustes step (rotation and
// translation, no scale), the turn limited to ±5°: each piece's orientation comes from its own
// flattening (its grain or principal axis), so two pieces flattened separately may sit a slight
// turn apart, and a 2° turn already moves a piece's ends by 1.7 % of its size; a larger turn would
// put the grain off. The distance of two aligned pieces is the symmetric Hausdorff distance of
// their sew lines: every sew line sampled at its vertices and at most 1/512 of the size apart, each
// sample's distance to the other piece's polylines, both ways, the largest. An unmirrored alignment
// within the tolerance is preferred to a mirrored one (a symmetric piece is then not reported as
// turned over).
#pragma once

#include <vector>

#include "flatten/pattern.h"

namespace qd::flatten {

struct PieceGroup {
  std::vector<int> members;    // indices into the pieces; the first, the lowest, represents them
  std::vector<char> mirrored;  // per member: 1 = a mirror image of the representative
  double difference = 0;       // percent of the representative's size: the largest distance
                               // between a member's sew line and the representative's, aligned
};

// pieces: the pattern pieces, their sew lines in `outlines`, all in one orientation on the sheet.
// tolerance: percent of a piece's size (the diagonal of its bounding box); 0 = every piece alone.
// Every piece is in exactly one group: in index order, each piece joins the earlier
// representative it fits with the smallest difference, or else represents a new group. Groups
// come in order of their representative; deterministic. Above kMaxSymmetryPieces pieces every
// piece is alone: each piece is compared with every group, so the time grows with the square
// of the count (100,000 one-triangle patches would take hours), and a pattern has tens.
constexpr size_t kMaxSymmetryPieces = 1000;
std::vector<PieceGroup> symmetric_groups(const std::vector<PatternPiece>& pieces, double tolerance);

}  // namespace qd::flatten
