// The bridge between the command's mesh tables and the segmentation.
// make_segment_problem: MeshFile + SegmentOptions -> qd::SegmentProblem (positions, triangles,
//   the file's patch ids when --keep-patches, selected faces from the PLY face `flags`
//   selection bit, parameters).
// segment_output_fields: the input's vertices unchanged, per-face quality = patch id and a colour
//   per patch (qd::patch_color). Throws qd::Error when the result has the wrong size.
#pragma once

#include "io/mesh_file.h"
#include "io/output_mesh.h"
#include "options.h"
#include "segment/segment_problem.h"
#include "segment/segment_result.h"

namespace qd::cli {

SegmentProblem make_segment_problem(const meshio::MeshFile& mesh, const SegmentOptions& options);

meshio::OutputFields segment_output_fields(const SegmentResult& result,
                                           const meshio::MeshFile& mesh);

}  // namespace qd::cli
