// The flatten job's view of qd::common: its shared vocabulary (Vec3, Positions, Triangles, Error,
// Progress, parallel_for, ...) is reachable unqualified inside qd::flatten.
#pragma once

namespace qd::common {}

namespace qd::flatten {
using namespace common;
}  // namespace qd::flatten
