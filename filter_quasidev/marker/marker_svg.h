// A marker as an SVG 1.1 document (W3C, "Scalable Vector Graphics 1.1"): the fabric as a
// rectangle of its width and length, each placed cut line as a closed path with its piece's
// label (a trailing "m" on mirrored copies) at its centre. One SVG user unit is one model unit;
// y points up on the marker and down in SVG, so it is flipped.
#pragma once

#include <ostream>

#include "marker.h"

namespace qd::marker {

void write_marker_svg(std::ostream& out, const Marker& marker, const flatten::Pattern& pattern);

}  // namespace qd::marker
