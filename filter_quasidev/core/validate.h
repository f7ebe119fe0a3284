// Checks a Problem before any work: throws qd::Error with a message that says what was wrong
// and what to do (DESIGN.md "Bad input"). Accepts odd but workable input silently.
#pragma once

#include "problem.h"
#include "topology.h"

namespace qd {

// Fewest faces a patch may have: fewer cannot give a Gauss image to fit (Step 1).
constexpr int kMinPatchFaces = 4;

// Zero-area threshold: a face is degenerate when its area < kZeroAreaRatio · AE².
constexpr double kZeroAreaRatio = 1e-12;

// Returns the topology it computed, so callers need not compute it again.
Topology validate(const Problem& problem);

}  // namespace qd
