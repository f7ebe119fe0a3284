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

// wrap/callback.h uses strcpy without including <cstring>, so it comes after it.
// clang-format off
#include <cstring>
#include <wrap/callback.h>  // vcg::CallBackPos
// clang-format on

#include "param.h"

class CMeshO;

namespace qdml {

// The user's value of one parameter, as MeshLab hands it back: a number (Real, Integer, Boolean
// 0/1, the index of a Choice in its enum) or a text (Text, SaveFile), by parameter name.
// Every generation lists exactly the filter's declared parameters (params/), in their order,
// with their names and types, so one .mlx serves meshlabserver 2020.09 and pymeshlab 2025.07.
using ParamValue = std::variant<double, std::string>;
using ParamValues = std::map<std::string, ParamValue>;

// MeshLab filter classes (menus, search) and parts of a mesh a filter changes or writes.
enum class FilterCategory { Smoothing, Quality, VertexColoring, FaceColoring, Texture };
enum class MeshPart {
  VertexPositions,
  VertexNormals,
  FaceNormals,
  VertexQuality,
  VertexColor,
  FaceQuality,
  FaceColor,
  WedgeTexCoord
};

// One figure a filter returns (pymeshlab: a value of the returned dict).
using Figure = std::variant<int, double, std::vector<double>>;

// A figure with one entry per item (per patch, per piece): field(item) for each, as doubles.
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

struct FilterSpec {
  std::string name;         // menu text = .mlx filter name
  std::string python_name;  // pymeshlab name
  std::string info;         // filterInfo text (HTML allowed)
  std::vector<FilterCategory> categories;
  std::vector<MeshPart> changes;  // the post-condition: everything a run may change
  // The parameters for mesh m, as declared (params/); a tooltip may say more about m, e.g. its
  // average edge length.
  std::function<std::vector<qd::params::ParamInfo>(const CMeshO& m)> parameters;
  // Runs the filter on m; has_face_quality: m's per-face quality is meaningful. cb may be null.
  std::function<FilterRun(CMeshO& m, bool has_face_quality, const ParamValues& values,
                          vcg::CallBackPos* cb)>
      run;
};

const std::vector<FilterSpec>& filter_table();

}  // namespace qdml
