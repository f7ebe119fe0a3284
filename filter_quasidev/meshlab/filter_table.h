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
// SaveFile: the path of a file the filter writes (MeshLab's file-save parameter, with a Browse
// button in the dialog; .mlx type RichSaveFile in both generations); empty = none.
enum class ParamKind { Float, Int, Bool, Enum, SaveFile };
struct ParamSpec {
  std::string name;                // snake_case, = pymeshlab keyword
  std::string label;               // dialog label
  std::string tooltip;             // dialog tooltip
  ParamKind kind = ParamKind::Float;
  double value = 0;                // default: the float, the int, 0/1, or the enum index
  std::vector<std::string> items;  // Enum only: item texts (pymeshlab accepts them by text)
  std::string extension;           // SaveFile only: the file type, e.g. ".svg" (default path "")
};

// The user's value of one parameter: a number as ParamSpec::value (float, int, 0/1, enum
// index), or the text of a SaveFile path.
using ParamValue = std::variant<double, std::string>;
using ParamValues = std::map<std::string, ParamValue>;

// The number given for `name`, or `fallback` when values do not hold it.
double number_value(const ParamValues& values, const std::string& name, double fallback);
// The same rounded to a whole number (Int and Enum parameters).
int whole_value(const ParamValues& values, const std::string& name, int fallback);
// The same as a switch (Bool parameters): any value but 0 is on.
bool flag_value(const ParamValues& values, const std::string& name, bool fallback);
// The text given for `name` (a SaveFile path), or "" when values do not hold it.
std::string text_value(const ParamValues& values, const std::string& name);

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
  // The parameter table for mesh m (defaults may depend on it, e.g. its average edge length).
  std::function<std::vector<ParamSpec>(const CMeshO& m)> parameters;
  // Runs the filter on m; has_face_quality: m's per-face quality is meaningful. cb may be null.
  std::function<FilterRun(CMeshO& m, bool has_face_quality, const ParamValues& values,
                          vcg::CallBackPos* cb)>
      run;
};

const std::vector<FilterSpec>& filter_table();

}  // namespace qdml
