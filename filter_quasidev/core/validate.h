// Checks a Problem before any work: throws qd::Error with a message that says what was wrong
// and what to do (DESIGN.md "Bad input"). Accepts odd but workable input: silently, or with a
// warning where part of the mesh is left as it is.
#pragma once

#include <string>
#include <vector>

#include "problem.h"
#include "topology.h"

namespace qd {

// Zero-area threshold: a face is degenerate when its area < kZeroAreaRatio · AE².
constexpr double kZeroAreaRatio = 1e-12;

// Returns the topology it computed, so callers need not compute it again. Fails only when
// nothing can be processed: non-manifold edges and patches too small to fit are kept as they
// are (see warnings()).
Topology validate(const Problem& problem);

// One line per part of the mesh the run keeps as it is (vertices on non-manifold edges,
// patches of fewer than kMinPatchFaces faces), with a count, the first example and what to do.
std::vector<std::string> warnings(const Topology& topology);

}  // namespace qd
