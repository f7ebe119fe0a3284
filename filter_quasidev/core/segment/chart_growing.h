// D-Charts' chart growing (Julius, Kraevoy, Sheffer 2005): every chart grows from its seed face
// over the face graph, one face at a time, the face of lowest growing cost (growing_cost.h)
// over all charts first. A face joins a chart only while its deviation from the chart's cone is
// at most the limit, so faces no chart fits stay free; the caller seeds new charts there.
// Ties are broken by face index, then chart index: the result is deterministic.
#pragma once

#include <vector>

#include "segment/chart.h"
#include "segment/face_geometry.h"
#include "segment/face_graph.h"
#include "segment/segment_params.h"

namespace qd::segment {

struct GrowSettings {
  double limit = 0.0;  // largest deviation, radians
  CostWeights weights;
};

// label: per face a chart index, kFree or kOutside (chart.h). Charts whose seed is free grow
// into the free faces; faces already in a chart stay there. Returns the faces taken, in order.
std::vector<int> grow_charts(const FaceGraph& graph, const FaceGeometry& g,
                             const std::vector<Chart>& charts, std::vector<int>& label,
                             const GrowSettings& settings);

}  // namespace qd::segment
