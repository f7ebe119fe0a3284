// Splitting charts to reach a target patch count larger than the fit needs. The chart that fits
// worst (largest root mean square error × area, ties to the larger area, then the lower index)
// is cut in two by D-Charts' growing and fitting restricted to its faces: one chart grows from
// its most interior face with its cone, one from its worst-fitting face with that face's plane,
// both admitting every face; the two are refitted, reseeded and regrown kSplitRounds times.
// A chart is cut only if both halves have the smallest size; otherwise the next is tried.
#pragma once

#include "segment/chart_growing.h"
#include "segment/face_geometry.h"
#include "segment/face_graph.h"
#include "segment/partition.h"
#include "segment/small_charts.h"

namespace qd::segment {

constexpr int kSplitRounds = 3;

// Returns the number of charts added. s.limit: the fit limit, radians.
int split_charts(Partition& p, const FaceGraph& graph, const FaceGeometry& g, const GrowSettings& s,
                 const MinimumSize& size, int target);

}  // namespace qd::segment
