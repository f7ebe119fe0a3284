// The marker the command writes: libnest2d's nesting (nest_marker.h) and the simple row-by-row
// placement (row_marker.h) are both made, and the shorter is kept. Measured on garments of a
// few large pieces (docs/cutting-room.md), nesting gains little or loses a little against rows,
// while on many irregular pieces it is 10-30 % shorter: trying both costs one cheap row
// placement and is never worse than either.
#pragma once

#include "marker.h"

namespace qd {

struct MarkerChoice {
  Marker nested, rows;
  bool nested_kept = true;  // the nesting is at most as long as the rows
  const Marker& kept() const { return nested_kept ? nested : rows; }
};

// width: the fabric's width (> 0); gap: the space between pieces.
MarkerChoice cut_marker(const Pattern& pattern, double width, double gap);

}  // namespace qd
