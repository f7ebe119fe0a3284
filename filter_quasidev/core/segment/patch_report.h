// The segmentation's result from its final charts: patch ids 0 … k−1 in the order of each
// chart's lowest face, and per patch its faces, area, cone and fit errors in degrees, boundary
// loops, Euler characteristic, whether it is a disk, the input patch it came from, and why it
// is over the limit if it is.
#pragma once

#include "segment/face_geometry.h"
#include "segment/partition.h"
#include "segment/segment_problem.h"
#include "segment/segment_result.h"

namespace qd::segment {

SegmentResult patch_report(const Partition& p, const SegmentProblem& problem,
                           const FaceGeometry& g);

}  // namespace qd::segment
