// The shared MeshLab adapter of the quasi-developable approximation: one source for every MeshLab
// generation (compiled once per plugin variant against that variant's CMeshO: 2020.09 float,
// 2025.07 float, 2025.07d double). It holds the filter's entry in filter_table() (texts,
// parameter table, figures), the conversion CMeshO <-> qd::Problem / qd::Result and the
// write-back. No numerics (the engine does them) and no plugin-API types (the per-generation
// plugin files map RichParameterList, logging and error reporting).
#pragma once

#include <string>
#include <vector>

#include "approximate/params.h"
#include "approximate/result.h"
#include "filter_table.h"
#include "run_outcome.h"

namespace qdml {

// The filter's entry in filter_table(): its texts, classes, post-condition, parameter_specs
// and a run that maps the values with settings_from_values, calls apply and returns the figures.
FilterSpec approximate_filter();

// The parameter table of the filter for mesh m. Defaults come from qd::Params; the tolerance
// default is the mesh's average edge length AE (shown in its tooltip); a tolerance of 0 (as
// written in sample_meshes/default.mlx) also means "1·AE of the mesh the filter runs on".
std::vector<ParamSpec> parameter_specs(const CMeshO& m);

// What the user chose. params.tolerance == 0 means 1·AE (resolved by apply()).
struct Settings {
  qd::Params params;
  bool use_patches = true;            // patch id per face from per-face quality, when present
  bool displacement_quality = false;  // per-vertex quality = displacement instead of K after
  bool colorize = true;               // colour ramp on the per-vertex quality
};

// Settings from the values read back by name (as ParamSpec::value: floats, ints, 0/1, enum
// indices). A name missing from `values` keeps its default.
Settings settings_from_values(const ParamValues& values);

using Outcome = RunOutcome<qd::Result>;

// Reads m (positions, faces; patch id per face = rounded per-face quality when has_face_quality
// and s.use_patches, else one patch; constrained = selected vertices; deleted elements skipped),
// runs the engine and ONLY on success writes back positions, per-vertex quality (K after or
// displacement) and, when s.colorize, per-vertex colour on a robust ramp, then face/vertex
// normals and the bbox.
// Nothing else of m changes (texture coordinates, face quality, face colours, selection).
// On failure m is untouched and Outcome::error says why. cb may be null.
Outcome apply(CMeshO& m, bool has_face_quality, const Settings& s, vcg::CallBackPos* cb);

}  // namespace qdml
