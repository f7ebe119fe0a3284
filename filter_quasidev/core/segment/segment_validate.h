// Checks a SegmentProblem before any work: throws qd::common::Error with one line saying what was
// wrong and what to do (docs/design.md "Bad input"). Non-manifold edges and inconsistently oriented
// faces are not errors: they are kept as patch borders (face_graph.h).
#pragma once

#include "segment/segment_problem.h"

namespace qd::segment {

void validate_segment(const SegmentProblem& problem);

}  // namespace qd::segment
