// The PLY document each job writes: the input document (output_mesh.h) with the result's columns.
// approximated_ply: the new positions (double, normals recomputed), per-vertex quality = K after
//   or displacement (settings.output_quality) and, with settings.colorize, its colour ramp over
//   the robust (2nd–98th percentile) range.
// segmented_ply: the input's vertices, per-face quality = patch id and a colour per patch
//   (qd::patch_color).
// flattened_ply: the input's vertices, per-face wedge texture coordinates (model units),
//   quality = signed stretch and its colour ramp (flatten/stretch_ramp.h).
// Throws qd::Error when the result does not have one entry per vertex (per face).
#pragma once

#include "approximate/result.h"
#include "approximate_settings.h"
#include "flatten/flatten_result.h"
#include "io/mesh_file.h"
#include "io/ply_file.h"
#include "segment/segment_result.h"

namespace qd::meshio {

PlyFile approximated_ply(const MeshFile& mesh, const Result& result,
                         const params::ApproximateSettings& settings);
PlyFile segmented_ply(const MeshFile& mesh, const SegmentResult& result);
PlyFile flattened_ply(const MeshFile& mesh, const FlattenResult& result);

}  // namespace qd::meshio
