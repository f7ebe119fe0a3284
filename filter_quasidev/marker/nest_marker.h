// The nested marker: every piece of a pattern (its quantity, mirrored ones turned over) placed
// without overlap on a strip of fabric of a given width, the grainline along the fabric's
// length, as short as the nesting finds. Nesting by libnest2d (Tamás Mészáros, LGPL-3.0; the
// no-fit-polygon placer with NLopt's subplex along the no-fit polygons, first-fit selection,
// largest piece first) on the cut lines themselves, their no-fit polygons exact for concave
// pieces too (Clipper's Minkowski sum, libnest2d_nfp.h), so pieces interlock. Each cut line
// nests pushed out by 0.03 % of the width and simplified within that (few vertices keep it
// fast); libnest2d's placer is sequential for concave shapes and its parallel search keeps the
// first best start, so the marker is the same on every run.
#pragma once

#include "marker.h"

namespace qd::marker {

// width: the fabric's width (> 0); gap: the space left between pieces and from the selvages
// (>= 0). Pieces wider than the fabric (less the gap) are listed in Marker::unplaced.
Marker nest_marker(const flatten::Pattern& pattern, double width, double gap);

}  // namespace qd::marker
