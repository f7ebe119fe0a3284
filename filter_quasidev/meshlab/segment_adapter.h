// The MeshLab adapter of the segmentation into nearly developable patches (qd::segment), one
// source for every MeshLab generation like quasidev_adapter.h: the filter's entry in
// filter_table() (texts, classes, parameters from params/segment_params.h, figures), CMeshO ->
// qd::segment::SegmentProblem and the write-back of per-face quality = patch id and a colour per
// patch. No numerics, no plugin-API types.
#pragma once

#include <string>
#include <vector>

#include "filter_table.h"
#include "run_outcome.h"
#include "segment/segment_result.h"
#include "segment_settings.h"

namespace qdml {

// The filter's entry: "Quasi-Developable Segmentation", pymeshlab
// compute_segmentation_quasi_developable.
FilterSpec segment_filter();

using SegmentOutcome = RunOutcome<qd::segment::SegmentResult>;

// Reads m (live vertices and faces; patch ids from the per-face quality when has_face_quality
// and s.keep_patches; selected faces when s.selection_border), runs the segmentation and ONLY on
// success enables and writes per-face quality = patch id and per-face colour = patch colour.
// Nothing else of m changes. On failure m is untouched. cb may be null.
SegmentOutcome apply_segment(CMeshO& m, bool has_face_quality, const qd::params::SegmentSettings& s,
                             vcg::CallBackPos* cb);

}  // namespace qdml
