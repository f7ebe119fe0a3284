// The segmentation's entry point: a mesh → nearly developable patches, after D-Charts (Julius,
// Kraevoy, Sheffer, "D-Charts: Quasi-Developable Mesh Segmentation", Computer Graphics Forum
// 24(3), Eurographics 2005).
//
// Steps: input regions (existing patches, selection, components) whose faces fit one cone
// within the limit are kept whole; the rest is segmented by D-Charts' Lloyd iteration (lloyd.h)
// over the face graph with creases cut (face_graph.h); then adjacent charts are merged while
// their union fits (D-Charts' merging), charts below the smallest size go into the neighbour
// they fit best, and, with a target count, the best-fitting pairs are merged (chart_merging.h)
// or the worst-fitting charts split (split_charts.h) until it is met. Deterministic: the same
// patches for any number of threads.
#pragma once

#include "common/progress.h"
#include "segment/common_names.h"
#include "segment/segment_problem.h"
#include "segment/segment_result.h"

namespace qd::segment {

// Throws qd::common::Error on bad input (segment_validate.h); the input is never modified.
SegmentResult segment(const SegmentProblem& problem, const Progress& progress = {});

}  // namespace qd::segment
