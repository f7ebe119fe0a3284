// The cutting pattern as an SVG 1.1 document (W3C, "Scalable Vector Graphics 1.1"): per piece a
// group with its cut line(s) solid and, when the seam allowance is not 0, its sew line(s)
// dashed; notch ticks cut through the allowance into the piece; the grainline as a line with an
// arrowhead at both ends; the label's lines (name, piece, quantity, size; piece_marks.h) at its
// centroid. A scale bar with its length under the pieces. One SVG user unit is one model unit; y
// points up in the pattern and down in SVG, so it is flipped.
#pragma once

#include <ostream>
#include <string>

#include "flatten/pattern.h"

namespace qd::io {

// unit: the model's length unit, written on the scale bar and the labels; "mm", "cm" or "in"
// also give the document that physical size, so it prints at 1:1. Empty: "model units", no
// physical size.
void write_svg(std::ostream& out, const flatten::Pattern& pattern, const std::string& unit = "");

}  // namespace qd::io
