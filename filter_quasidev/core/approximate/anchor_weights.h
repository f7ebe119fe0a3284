// MLS soft-anchor weights (paper §5.3, Eq. 15) for every vertex of a group.
#pragma once

#include <vector>

#include "approximate/common_names.h"
#include "common/mesh.h"

namespace qd::approximate {

// w(v) = 1 / (d(v, V_cstr)/AE + ε²), ε = 0.001, with d the Euclidean distance to the nearest
// constrained vertex measured in units of the average edge length AE (keeps the weight
// scale-invariant). All weights are 0 when no vertex is constrained.
// threads: how many threads may share the nearest-neighbour queries (the result does not
// depend on it).
std::vector<double> mls_weights(const Positions& V, const std::vector<char>& fixed, double ae,
                                int threads = 1);

}  // namespace qd::approximate
