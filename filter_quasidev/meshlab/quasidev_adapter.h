// The shared MeshLab adapter of the quasi-developable approximation: one source for every MeshLab
// generation (compiled once per plugin variant against that variant's CMeshO: 2020.09 float,
// 2025.07 float, 2025.07d double). It holds the filter's entry in filter_table() (texts,
// parameters from params/approximate_params.h, figures), the conversion CMeshO <->
// qd::approximate::Problem / qd::approximate::Result and the write-back. No numerics (the engine
// does them) and no plugin-API types (the per-generation plugin files map RichParameterList,
// logging and error reporting).
#pragma once

#include <string>
#include <vector>

#include "approximate/result.h"
#include "approximate_settings.h"
#include "filter_table.h"
#include "run_outcome.h"

namespace qdml {

// The filter's entry in filter_table(): its texts, classes, post-condition, parameters and a
// run that reads the settings (declared_parameters.h), calls apply and returns the figures.
FilterSpec approximate_filter();

// The declared parameters of the filter for mesh m; the tolerances' tooltips give m's average
// edge length AE.
std::vector<qd::params::ParamInfo> approximate_parameters(const CMeshO& m);

using Outcome = RunOutcome<qd::approximate::Result>;

// Reads m (positions, faces; patch id per face = rounded per-face quality when has_face_quality
// and s.use_patches, else one patch; constrained = selected vertices; deleted elements skipped),
// runs the engine with the tolerances in model units (qd::params::engine_params) and ONLY on
// success writes back positions, per-vertex quality (K after or displacement) and, when
// s.colorize, per-vertex colour on a robust ramp, then face/vertex normals and the bbox.
// Nothing else of m changes (texture coordinates, face quality, face colours, selection).
// On failure m is untouched and Outcome::error says why. cb may be null.
Outcome apply(CMeshO& m, bool has_face_quality, const qd::params::ApproximateSettings& s,
              vcg::CallBackPos* cb);

}  // namespace qdml
