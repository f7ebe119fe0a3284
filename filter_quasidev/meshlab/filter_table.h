// The filters of the plugin, one generation-neutral entry each: texts, MeshLab classes,
// post-condition, parameter table and a run function. Every plugin class (2020.09, 2025.07 and
// 2025.07d) lists exactly these filters in this order, their ids being the indices
// (plugin_table.h maps the fields to each API). Adding a filter is adding an entry to
// filter_table(); no plugin file changes.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <cstring>          // wrap/callback.h uses strcpy without including <cstring>
#include <wrap/callback.h>  // vcg::CallBackPos

class CMeshO;

namespace qdml {

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

// The user's values by parameter name, as ParamSpec::value: floats, ints, 0/1, enum indices.
using ParamValues = std::map<std::string, double>;

// MeshLab filter classes (menus, search) and parts of a mesh a filter changes or writes.
enum class FilterCategory { Smoothing, Quality, VertexColoring, FaceColoring };
enum class MeshPart {
  VertexPositions,
  VertexNormals,
  FaceNormals,
  VertexQuality,
  VertexColor,
  FaceQuality,
  FaceColor
};

// One figure a filter returns (pymeshlab: a value of the returned dict).
using Figure = std::variant<int, double, std::vector<double>>;

// The list figure of field(item) for every item (per patch, in id order).
template <typename Item, typename Field>
Figure figure_list(const std::vector<Item>& items, Field field) {
  std::vector<double> v;
  v.reserve(items.size());
  for (const Item& item : items) v.push_back(static_cast<double>(field(item)));
  return v;
}

// What one run of a filter did. On failure the mesh is unchanged and `error` says why.
struct FilterRun {
  bool ok = false;
  std::string error;                      // written for the user, when !ok
  std::vector<std::string> log;           // lines to log (also on failure)
  std::map<std::string, Figure> figures;  // on success
  std::vector<MeshPart> written;          // on success: the per-element data the run wrote
};

// The FilterRun of an adapter's outcome (fields ok, error, log, result): on success with
// figures(result) and `written`.
template <typename Outcome, typename Figures>
FilterRun filter_run(Outcome& outcome, Figures figures, std::vector<MeshPart> written) {
  FilterRun out;
  out.ok = outcome.ok;
  out.error = std::move(outcome.error);
  out.log = std::move(outcome.log);
  if (!out.ok) return out;
  out.figures = figures(outcome.result);
  out.written = std::move(written);
  return out;
}

struct FilterSpec {
  std::string name;         // menu text = .mlx filter name
  std::string python_name;  // pymeshlab name
  std::string info;         // filterInfo text (HTML allowed)
  std::vector<FilterCategory> categories;
  std::vector<MeshPart> changes;  // the post-condition: everything a run may change
  // The parameter table for mesh m (defaults may depend on it, e.g. its average edge length).
  std::function<std::vector<ParamSpec>(const CMeshO& m)> parameters;
  // Runs the filter on m; has_face_quality: m's per-face quality is meaningful. cb may be null.
  std::function<FilterRun(CMeshO& m, bool has_face_quality, const ParamValues& values,
                          vcg::CallBackPos* cb)>
      run;
};

const std::vector<FilterSpec>& filter_table();

}  // namespace qdml
