// The MeshLab adapter of the segmentation into nearly developable patches (qd::segment), one
// source for every MeshLab generation like quasidev_adapter.h: the filter's entry in
// filter_table() (texts, classes, parameter table, figures), CMeshO -> qd::SegmentProblem and the
// write-back of per-face quality = patch id and a colour per patch. No numerics, no plugin-API
// types.
#pragma once

#include <string>
#include <vector>

#include "filter_table.h"
#include "run_outcome.h"
#include "segment/segment_params.h"
#include "segment/segment_result.h"

namespace qdml {

// The filter's entry: "Quasi-Developable Segmentation", pymeshlab
// compute_segmentation_quasi_developable.
FilterSpec segment_filter();

// What the user chose.
struct SegmentSettings {
  qd::SegmentParams params;
  bool keep_patches = false;     // existing patches (per-face quality) kept where they fit
  bool selection_border = true;  // the border of the face selection is kept
};

// The parameter table (defaults from qd::SegmentParams and SegmentSettings), and the settings
// from the values read back by name (a name missing keeps its default).
std::vector<ParamSpec> segment_parameter_specs();
SegmentSettings segment_settings_from_values(const ParamValues& values);

using SegmentOutcome = RunOutcome<qd::SegmentResult>;

// Reads m (live vertices and faces; patch ids from the per-face quality when has_face_quality
// and s.keep_patches; selected faces when s.selection_border), runs the segmentation and ONLY on
// success enables and writes per-face quality = patch id and per-face colour = patch colour.
// Nothing else of m changes. On failure m is untouched. cb may be null.
SegmentOutcome apply_segment(CMeshO& m, bool has_face_quality, const SegmentSettings& s,
                             vcg::CallBackPos* cb);

}  // namespace qdml
