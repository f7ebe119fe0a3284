// Where a flattened piece overlaps itself along its boundary: pairs of boundary edges that
// cross in the plane. A disk flattened without flipped faces and without boundary crossings is
// embedded (a locally injective map whose boundary is a simple curve is injective), so these two
// counts decide whether a piece can be cut out as it is.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

namespace qd::flatten {

// segments: boundary edges as vertex pairs into uv. Returns per segment 1 if it properly
// crosses another segment that shares no vertex with it. A uniform grid of cells about one
// segment long keeps this near linear in the number of segments.
std::vector<char> crossing_segments(const Eigen::MatrixX2d& uv,
                                    const std::vector<std::array<int, 2>>& segments);

}  // namespace qd::flatten
