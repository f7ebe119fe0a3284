// The cutting pattern as an SVG 1.1 document (W3C, "Scalable Vector Graphics 1.1"): per piece a
// group with its outline(s) as closed paths, notch ticks at its seam vertices (pointing into
// the piece) and its label at its centroid; a scale bar with its length under the pieces.
// One SVG user unit is one model unit; y points up in the pattern and down in SVG, so it is
// flipped.
#pragma once

#include <ostream>
#include <string>

#include "flatten/pattern.h"

namespace qd {

// unit: the model's length unit, written on the scale bar; "mm", "cm" or "in" also give the
// document that physical size, so it prints at 1:1. Empty: "model units", no physical size.
void write_svg(std::ostream& out, const Pattern& pattern, const std::string& unit = "");

}  // namespace qd
