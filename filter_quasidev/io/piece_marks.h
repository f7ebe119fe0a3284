// What every pattern writer marks on a piece besides its lines: the grainline, the notch ticks
// and the label's text. Pattern-making convention (e.g. Armstrong, "Patternmaking for Fashion
// Design"): the grainline is a straight line with an arrowhead at both ends, drawn along the
// fabric's grain through the middle of the piece; a notch is cut through the seam allowance.
#pragma once

#include <string>
#include <vector>

#include "flatten/pattern.h"

namespace qd::io {

struct Segment2 {
  Eigen::Vector2d from, to;
};

// Bounding box of the piece's cut line(s).
Eigen::AlignedBox2d cut_box(const flatten::PatternPiece& piece);

// The grainline: through label_at along grain, 60 % of the cut line's extent along the grain,
// shortened where it would come within 10 % of the sew line (of the way from label_at to it).
Segment2 grainline(const flatten::PatternPiece& piece);

// A notch's tick: from where it crosses the cut line through the sew line, then `beyond` further
// into the piece.
Segment2 notch_tick(const flatten::Notch& notch, double beyond);

// The label's lines: the name (if any), "Piece <label>", "Cut <quantity>" (with " (<n> mirrored)"
// when some are turned over), and the cut line's size "<w> <times> <h> <unit>" (unit "" = "model
// units"); times is the multiplication sign the format can write.
std::vector<std::string> label_lines(const flatten::PatternPiece& piece, const std::string& unit,
                                     const std::string& times);

// The label's text height: `height`, or less so that the lines (about 0.6 height per character
// wide, 1.2 height apart) fit in 80 % of the width and half the height of the sew line's box.
double label_height(const flatten::PatternPiece& piece, const std::vector<std::string>& lines,
                    double height);

}  // namespace qd::io
