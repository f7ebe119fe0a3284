// The shared MeshLab adapter of the quasi-developable approximation: one source for every MeshLab
// generation (compiled once per plugin variant against that variant's CMeshO: 2020.09 float,
// 2025.07 float, 2025.07d double). It holds the filter's texts, its parameter table, the
// conversion CMeshO <-> qd::Problem / qd::Result and the write-back. No numerics (the engine
// does them) and no plugin-API types (the per-generation plugin files map RichParameterList,
// logging and error reporting).
#pragma once

#include <map>
#include <string>
#include <vector>

#include <cstring>          // wrap/callback.h uses strcpy without including <cstring>
#include <wrap/callback.h>  // vcg::CallBackPos

#include "approximate/params.h"
#include "approximate/result.h"

class CMeshO;

namespace qdml {

// Menu text (= .mlx filter name), pymeshlab name, and the filterInfo text (HTML allowed).
std::string filter_name();
std::string python_filter_name();
std::string filter_info();

// One user parameter. Every generation declares exactly these, in this order, with these names
// and types, so one .mlx serves meshlabserver 2020.09 and pymeshlab 2025.07.
enum class ParamKind { Float, Int, Bool, Enum };
struct ParamSpec {
  std::string name;                // snake_case, = pymeshlab keyword
  std::string label;               // dialog label
  std::string tooltip;             // dialog tooltip
  ParamKind kind = ParamKind::Float;
  double value = 0;                // default: the float, the int, 0/1, or the enum index
  std::vector<std::string> items;  // Enum only: item texts (pymeshlab accepts them by text)
};

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
Settings settings_from_values(const std::map<std::string, double>& values);

struct Outcome {
  bool ok = false;
  std::string error;              // the reason, written for the user, when !ok
  std::vector<std::string> log;   // lines to log (also on failure: what was read from the mesh)
  qd::Result result;              // the engine's result when ok
};

// Reads m (positions, faces; patch id per face = rounded per-face quality when has_face_quality
// and s.use_patches, else one patch; constrained = selected vertices; deleted elements skipped),
// runs the engine and ONLY on success writes back positions, per-vertex quality (K after or
// displacement) and, when s.colorize, per-vertex colour on a robust ramp, then face/vertex
// normals and the bbox.
// Nothing else of m changes (texture coordinates, face quality, face colours, selection).
// On failure m is untouched and Outcome::error says why. cb may be null.
Outcome apply(CMeshO& m, bool has_face_quality, const Settings& s, vcg::CallBackPos* cb);

}  // namespace qdml
