// The segment job's view of qd::common: its shared vocabulary (Vec3, Positions, Triangles, Error,
// Progress, parallel_for, ...) is reachable unqualified inside qd::segment.
#pragma once

namespace qd::common {}

namespace qd::segment {
using namespace common;
}  // namespace qd::segment
