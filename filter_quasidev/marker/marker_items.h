// The pieces a marker places: each pattern piece `quantity` times, `mirrored` of them turned
// over, each turned so that its grainline runs along the fabric's length (+x). Shared by the
// nested and the row-by-row marker.
#pragma once

#include <vector>

#include "marker.h"

namespace qd::marker {

// One copy of a piece before placement: its cut line (the outer loop) mirrored and turned,
// as a placement with a zero offset.
std::vector<MarkerPlacement> marker_items(const flatten::Pattern& pattern);

// Moves a placement by d.
void translate_placement(MarkerPlacement& p, const Eigen::Vector2d& d);

}  // namespace qd::marker
