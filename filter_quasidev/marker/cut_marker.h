// The marker the command writes: libnest2d's nesting (nest_marker.h) and the simple row-by-row
// placement (row_marker.h) are both made, and the shorter is kept: neither wins on every
// garment (docs/measurements-behind-the-code.md), and the rows cost little.
#pragma once

#include "marker.h"

namespace qd::marker {

struct MarkerChoice {
  Marker nested, rows;
  bool nested_kept = true;  // the nesting is at most as long as the rows
  const Marker& kept() const { return nested_kept ? nested : rows; }
};

// width: the fabric's width (> 0); gap: the space between pieces.
MarkerChoice cut_marker(const flatten::Pattern& pattern, double width, double gap);

}  // namespace qd::marker
