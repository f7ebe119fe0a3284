// Ordering the skeleton pixels of the digital image into one curve (§5.1; the paper leaves
// the ordering open, docs/design.md "The algorithm", Step 1.4, fixes it): neighbour graph ->
// minimum spanning tree -> longest path (tree diameter) as the backbone, spurs dropped; on a
// θ-periodic image the loop that winds once around θ is taken instead, giving a closed curve.
//   order_skeleton: skeleton points (pixel units) -> ordered polyline (x unwrapped)
//   extend_ends:    ordered open polyline + samples -> polyline reaching the outermost samples
#pragma once

#include <vector>

#include "approximate/digital_image.h"

namespace qd::approximate {

struct OrderedSkeleton {
  std::vector<Vec2> points;   // pixel coordinates in curve order; x unwrapped on periodic images
  bool closed = false;        // the curve is a loop (then it winds once around θ)
  Vec2 shift = Vec2::Zero();  // closed: the point after the last one is points[0] + shift
};

// width: image width in pixels (the period when `periodic`).
OrderedSkeleton order_skeleton(const std::vector<SkeletonPoint>& points, int width, bool periodic);

// Replaces both ends of an open polyline (the points within `trim` pixels of an end point, where
// the ridge curls as the point distribution ends; kept when the ends are closer than 3·trim)
// by prolongations along circular arcs (tangent and curvature from the next 4·trim pixels,
// turning at most 45°), in steps of one pixel, as far as the samples within `reach` of the
// arc project beyond the end (98th percentile), so faces near the ends of the Gauss image are not
// all pulled onto the end point. samples in pixel units; period = image width when periodic, else
// 0.
void extend_ends(std::vector<Vec2>& polyline, const std::vector<Vec2>& samples, double reach,
                 double period, double trim);

}  // namespace qd::approximate
