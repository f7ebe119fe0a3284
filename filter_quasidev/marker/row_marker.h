// The simple marker the nested one is compared with: the same pieces, turned the same way for
// the grain, placed by their bounding boxes in rows across the fabric's width (shelf packing,
// next-fit decreasing by length): each row is as long as its longest piece, the pieces are
// stacked across the width until the next one does not fit, then a new row starts.
#pragma once

#include "marker.h"

namespace qd::marker {

// width: the fabric's width (> 0); gap: the space left between pieces and rows.
Marker row_marker(const flatten::Pattern& pattern, double width, double gap);

}  // namespace qd::marker
