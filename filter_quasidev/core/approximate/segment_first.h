// One default path for a mesh without patches (closed, scanned, CAD; beyond the paper, which
// assumes the designer's patches): when the mesh has no patch ids and is closed, or its normals
// fill the sphere so that no one Gauss-image curve fits it (Step 1 fails), it is first split
// into nearly developable patches (segment.h, D-Charts, with kSegmentFirstMaxErrorDeg) and the
// patches are solved with free seams, so curvature gathers on the seams, which move, instead of
// being spread over every vertex. SegmentFirst::Never keeps such a mesh one patch,
// SegmentFirst::Always splits every mesh without patch ids.
#pragma once

#include <string>
#include <vector>

#include "approximate/common_names.h"
#include "approximate/problem.h"
#include "common/topology.h"

namespace qd::approximate {

// D-Charts' largest fit error for this path. At 30° the shared spot, rocker arm and cow split
// into 26, 59 and 77 patches (at the segmentation's own default of 20°: 43, 142 and 140), and
// the approximation after it removes more G_ABD at a comparable surface distance
// (docs/robustness.md, "Meshes without patches").
constexpr double kSegmentFirstMaxErrorDeg = 30.0;

struct SegmentFirstPlan {
  bool segment = false;
  std::string why;  // said in the log
};

// Whether the problem takes the segment-first path, and why.
SegmentFirstPlan plan_segment_first(const Problem& problem, const Topology& topology);

// The problem with the segmentation's patch ids and free seams. Throws qd::common::Error when the
// segmentation cannot run on the mesh.
Problem segmented(const Problem& problem);

}  // namespace qd::approximate
