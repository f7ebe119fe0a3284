// The bridge between the command's mesh tables and the segmentation.
// make_segment_problem: MeshDocument + SegmentOptions -> qd::segment::SegmentProblem (positions,
// triangles,
//   the file's patch ids when --keep-patches, selected faces from the PLY face `flags`
//   selection bit, parameters).
#pragma once

#include "io/mesh_document.h"
#include "options.h"
#include "segment/segment_problem.h"

namespace qd::cli {

segment::SegmentProblem make_segment_problem(const io::MeshDocument& mesh,
                                             const SegmentOptions& options);

}  // namespace qd::cli
