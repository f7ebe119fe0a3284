// Charts below the smallest size after merging: parts too curved for any chart of that size to
// fit within the limit. Each grows to the smallest size by taking faces from its neighbours,
// the faces its own cone fits best first, so the part becomes one patch of the smallest size
// (over the limit, OverLimit::SmallestSize) and its neighbours keep fitting (they only lose
// faces). A neighbour gives a face only while it keeps the smallest size and stays
// edge-connected without it (checked by a short search around the face). Charts that cannot
// reach the size this way are left to MergeRule::SmallCharts (chart_merging.h).
#pragma once

#include "segment/face_geometry.h"
#include "segment/face_graph.h"
#include "segment/partition.h"

namespace qd::segment {

struct MinimumSize {
  int faces = 1;
  double area = 0.0;  // model units
};

// Returns the number of charts that reached the size. limit: radians, to mark the over-limit.
int grow_small_charts(Partition& p, const FaceGraph& graph, const FaceGeometry& g,
                      const MinimumSize& size, double limit);

}  // namespace qd::segment
