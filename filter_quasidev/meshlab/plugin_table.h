// What every plugin class does with filter_table(), written once against the names the MeshLab
// 2020.09 and 2025.07 APIs share (RichParameterList, RichFloat/Int/Bool/Enum, MeshModel::MM_*,
// the FilterClass bits) and the one they spell differently (the file-save parameter:
// RichSaveFile in 2020.09, RichFileSave in 2025.07; "RichSaveFile" in .mlx files of both). Included
// by filter_plugin_2020.cpp and filter_plugin_2025.cpp after their MeshLab interface header, so
// each compiles it against its own generation.
#pragma once

#include <charconv>
#include <cstdlib>
#include <string>
#include <type_traits>
#include <vector>

#include "declared_parameters.h"
#include "filter_table.h"

#if __has_include(<common/parameters/rich_parameter/rich_file_save.h>)
using RichSaveFileParameter = RichFileSave;  // MeshLab 2025.07
#else
using RichSaveFileParameter = RichSaveFile;  // MeshLab 2020.09
#endif

namespace qdml {

inline QString qs(const std::string& s) { return QString::fromStdString(s); }

// The entry of filter id `id` (its index in filter_table()), or null for an unknown id.
inline const FilterSpec* filter_spec(int id) {
  const std::vector<FilterSpec>& table = filter_table();
  return id >= 0 && static_cast<std::size_t>(id) < table.size()
             ? &table[static_cast<std::size_t>(id)]
             : nullptr;
}

// A text of filter `id` (text: &FilterSpec::name, python_name or info); empty for an unknown id.
inline QString filter_text(int id, std::string FilterSpec::*text) {
  const FilterSpec* f = filter_spec(id);
  return f ? qs(f->*text) : QString();
}

// The filter's MeshLab classes as the generation's FilterClass (Interface: MeshFilterInterface
// or FilterPlugin).
template <typename Interface>
typename Interface::FilterClass filter_class(const FilterSpec& f) {
  int bits = 0;
  for (const FilterCategory c : f.categories) switch (c) {
      case FilterCategory::Smoothing:
        bits |= Interface::Smoothing;
        break;
      case FilterCategory::Quality:
        bits |= Interface::Quality;
        break;
      case FilterCategory::VertexColoring:
        bits |= Interface::VertexColoring;
        break;
      case FilterCategory::FaceColoring:
        bits |= Interface::FaceColoring;
        break;
      case FilterCategory::Texture:
        bits |= Interface::Texture;
        break;
    }
  return typename Interface::FilterClass(bits);
}

// MeshModel's data mask of the given parts.
inline int mesh_mask(const std::vector<MeshPart>& parts) {
  int mask = MeshModel::MM_NONE;
  for (const MeshPart p : parts) switch (p) {
      case MeshPart::VertexPositions:
        mask |= MeshModel::MM_VERTCOORD;
        break;
      case MeshPart::VertexNormals:
        mask |= MeshModel::MM_VERTNORMAL;
        break;
      case MeshPart::FaceNormals:
        mask |= MeshModel::MM_FACENORMAL;
        break;
      case MeshPart::VertexQuality:
        mask |= MeshModel::MM_VERTQUALITY;
        break;
      case MeshPart::VertexColor:
        mask |= MeshModel::MM_VERTCOLOR;
        break;
      case MeshPart::FaceQuality:
        mask |= MeshModel::MM_FACEQUALITY;
        break;
      case MeshPart::FaceColor:
        mask |= MeshModel::MM_FACECOLOR;
        break;
      case MeshPart::WedgeTexCoord:
        mask |= MeshModel::MM_WEDGTEXCOORD;
        break;
    }
  return mask;
}

// The tooltip: the parameter's help, then its unit and range.
inline QString tooltip(const qd::params::ParamInfo& p) {
  const std::string unit = qd::params::unit_name(p.unit), range = qd::params::range_text(p.range);
  std::string tail = unit;
  if (!range.empty()) tail += (tail.empty() ? "" : "; ") + range;
  return qs(p.help + (tail.empty() ? "" : " (" + tail + ")"));
}

// Adds the filter's parameters for mesh m to `list`, in declaration order (addParam stores a
// copy). Real: RichFloat, Integer: RichInt, Boolean: RichBool, Choice: RichEnum, Text:
// RichString, SaveFile: the file-save parameter.
inline void add_parameters(const FilterSpec& f, const CMeshO& m, RichParameterList& list) {
  using qd::params::Type;
  for (const qd::params::ParamInfo& p : f.parameters(m)) {
    const QString name = qs(p.name), label = qs(p.label), tip = tooltip(p);
    const qd::params::Value& v = p.default_value;
    switch (p.type) {
      case Type::Real:
        list.addParam(RichFloat(name, static_cast<Scalarm>(std::get<double>(v)), label, tip));
        break;
      case Type::Integer:
        list.addParam(RichInt(name, static_cast<int>(std::get<double>(v)), label, tip));
        break;
      case Type::Boolean:
        list.addParam(RichBool(name, std::get<double>(v) != 0, label, tip));
        break;
      case Type::Choice: {
        QStringList items;
        for (const std::string& item : p.choices) items << qs(item);
        list.addParam(RichEnum(name, choice_index(p, std::get<std::string>(v)), items, label, tip));
        break;
      }
      case Type::Text:
        list.addParam(RichString(name, qs(std::get<std::string>(v)), label, tip));
        break;
      case Type::SaveFile:
        list.addParam(RichSaveFileParameter(name, QString(), qs(p.extension), label, tip));
        break;
    }
  }
}

// A RichFloat's value as the user typed it. It holds a float in MeshLab 2020.09 and in the 2025.07
// application (a double in pymeshlab): 0.03 arrives as 0.0299999993. The shortest decimal that
// gives the same float is the text the user typed, so read back through it the value is the
// command's for the same text (after 30 iterations of auto's stronger angle-defect rows, runs at
// 0.03 and at 0.0299999993 part by 1e-4 of the diagonal).
template <typename Real>
double as_typed(Real value) {
  if constexpr (std::is_same_v<Real, float>) {
    char text[32];
    *std::to_chars(text, text + sizeof text - 1, value).ptr = '\0';
    return std::strtod(text, nullptr);
  } else {
    return static_cast<double>(value);
  }
}

// The user's values by name, for the filter's parameters present in `params`.
inline ParamValues read_values(const FilterSpec& f, const CMeshO& m,
                               const RichParameterList& params) {
  using qd::params::Type;
  ParamValues values;
  for (const qd::params::ParamInfo& p : f.parameters(m)) {
    const QString name = qs(p.name);
    if (!params.hasParameter(name)) continue;
    switch (p.type) {
      case Type::Real:
        values[p.name] = as_typed(params.getFloat(name));
        break;
      case Type::Integer:
        values[p.name] = static_cast<double>(params.getInt(name));
        break;
      case Type::Boolean:
        values[p.name] = params.getBool(name) ? 1.0 : 0.0;
        break;
      case Type::Choice:
        values[p.name] = static_cast<double>(params.getEnum(name));
        break;
      case Type::Text:
        values[p.name] = params.getString(name).toStdString();
        break;
      case Type::SaveFile:
        values[p.name] = params.getSaveFileName(name).toStdString();
        break;
    }
  }
  return values;
}

}  // namespace qdml
