// The document each job writes: a copy of the input document with the result's columns
// (output_mesh.h).
// approximated_document: the new positions (double, normals recomputed), per-vertex quality = K
// after
//   or displacement (settings.output_quality) and, with settings.colorize, its colour ramp over
//   the robust (2nd–98th percentile) range.
// segmented_document: the input's vertices, per-face quality = patch id and a colour per patch
//   (qd::segment::patch_color).
// flattened_document: the input's vertices, per-face wedge texture coordinates (model units),
//   quality = signed stretch and its colour ramp (flatten/stretch_ramp.h).
// Throws qd::common::Error when the result does not have one entry per vertex (per face).
#pragma once

#include "approximate/result.h"
#include "approximate_settings.h"
#include "flatten/flatten_result.h"
#include "io/mesh_document.h"
#include "segment/segment_result.h"

namespace qd::io {

MeshDocument approximated_document(const MeshDocument& mesh, const approximate::Result& result,
                                   const params::ApproximateSettings& settings);
MeshDocument segmented_document(const MeshDocument& mesh, const segment::SegmentResult& result);
MeshDocument flattened_document(const MeshDocument& mesh, const flatten::FlattenResult& result);

}  // namespace qd::io
