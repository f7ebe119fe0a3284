// The seam allowance: the cut line of a pattern piece is its sew line grown outward by the
// allowance, with Clipper's polygon offset (Angus Johnson, Clipper 6.4.2, ClipperOffset) and
// mitred corners whose spikes are cut off at twice the allowance, as cutting rooms square off
// a sharp corner's allowance instead of letting it run to a point.
#pragma once

#include <vector>

#include "flatten/pattern.h"

namespace qd::flatten {

constexpr double kAllowanceReach = 2;  // the cut line lies at most this many allowances outside

// The cut lines of the region the sew lines bound (an outer loop, and any holes, in either
// orientation as long as holes run opposite to their outer loop): outer loops counter-clockwise,
// holes clockwise (faces to the left, as pattern_piece gives them). allowance 0 returns the
// sew lines unchanged.
std::vector<Outline> cut_lines(const std::vector<Outline>& sew_lines, double allowance);

// Gives the piece its cut lines (cut_lines of its sew lines) and each notch the point where
// it is cut through the allowance: the nearest crossing of the ray from `at` along -inward
// with the cut lines (`at` itself when the allowance is 0).
void add_seam_allowance(PatternPiece& piece, double allowance);

}  // namespace qd::flatten
