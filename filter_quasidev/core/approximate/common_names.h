// The approximate job's view of qd::common: its shared vocabulary (Vec3, Positions, Triangles,
// Error, Progress, parallel_for, ...) is reachable unqualified inside qd::approximate.
#pragma once

namespace qd::common {}

namespace qd::approximate {
using namespace common;
}  // namespace qd::approximate
