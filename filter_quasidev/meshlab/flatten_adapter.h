// The shared MeshLab adapter of the flattening (core/flatten): one source for every MeshLab
// generation, compiled once per plugin variant against its CMeshO. It holds the filter's entry
// in filter_table() (texts, parameters from params/flatten_params.h, figures), the conversion
// CMeshO -> qd::flatten::FlattenProblem and the write-back of qd::flatten::FlattenResult. No
// numerics (the engine does them) and no plugin-API types (the per-generation plugin files map
// them).
#pragma once

#include <string>
#include <vector>

#include "filter_table.h"
#include "flatten/flatten_result.h"
#include "flatten_settings.h"
#include "run_outcome.h"

namespace qdml {

// The filter's entry in filter_table().
FilterSpec flatten_filter();

using FlattenOutcome = RunOutcome<qd::flatten::FlattenResult>;

// Reads m (positions, faces; patch id per face = rounded per-face quality when has_face_quality,
// else one patch; deleted elements skipped), flattens it, writes the pattern files asked for
// (each atomically: an existing file is replaced only when all are written) and ONLY then writes
// on m, per live face: wedge texture coordinates in model units, quality = signed stretch and
// colour on a ramp symmetric about 0 (flatten/stretch_ramp.h). Nothing else of m changes. On
// failure m and the files are untouched and FlattenOutcome::error says why. cb may be null.
FlattenOutcome apply_flatten(CMeshO& m, bool has_face_quality, const qd::params::FlattenSettings& s,
                             vcg::CallBackPos* cb);

}  // namespace qdml
