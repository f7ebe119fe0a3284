// The human-readable lines of a segmentation report, shared by the command and the filters.
#pragma once

#include <string>
#include <vector>

#include "segment/segment_params.h"
#include "segment/segment_result.h"

namespace qd::segment {

// "plane", "cylinder" or "cone" for a proxy whose apex angle is within kKindToleranceDeg of 0°,
// of 90°, or neither.
constexpr double kKindToleranceDeg = 0.5;
const char* proxy_kind(const ConeProxy& proxy);

// Why a patch is over the limit, and what the user can do; empty for OverLimit::No.
std::string over_limit_text(OverLimit over, const SegmentParams& params);

// One line per patch: faces, area, proxy, fit errors, boundary loops, disk or not, and why it is
// over the limit if it is.
std::string patch_line(int id, const SegmentPatch& patch, const SegmentParams& params);

// What was kept as a border (non-manifold or inconsistently oriented edges), left over the limit
// or below the smallest size, or kept the target count from being met, and what to do about it.
std::vector<std::string> segment_warnings(int nonmanifold_edges, int misoriented_edges,
                                          const SegmentResult& r, const SegmentParams& q);

// The warnings, one line per patch and a summary (faces: the mesh's face count).
std::vector<std::string> segment_log(const SegmentResult& r, int faces, const SegmentParams& q);

}  // namespace qd::segment
