// What every plugin class does with filter_table(), written once against the names the MeshLab
// 2020.09 and 2025.07 APIs share (RichParameterList, RichFloat/Int/Bool/Enum, MeshModel::MM_*,
// the FilterClass bits) and the one they spell differently (the file-save parameter:
// RichSaveFile in 2020.09, RichFileSave in 2025.07; "RichSaveFile" in .mlx files of both). Included by filter_plugin_2020.cpp and filter_plugin_2025.cpp after
// their MeshLab interface header, so each compiles it against its own generation.
#pragma once

#include <string>
#include <vector>

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
  return id >= 0 && static_cast<std::size_t>(id) < table.size() ? &table[static_cast<std::size_t>(id)]
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
      case FilterCategory::Smoothing: bits |= Interface::Smoothing; break;
      case FilterCategory::Quality: bits |= Interface::Quality; break;
      case FilterCategory::VertexColoring: bits |= Interface::VertexColoring; break;
      case FilterCategory::FaceColoring: bits |= Interface::FaceColoring; break;
      case FilterCategory::Texture: bits |= Interface::Texture; break;
    }
  return typename Interface::FilterClass(bits);
}

// MeshModel's data mask of the given parts.
inline int mesh_mask(const std::vector<MeshPart>& parts) {
  int mask = MeshModel::MM_NONE;
  for (const MeshPart p : parts) switch (p) {
      case MeshPart::VertexPositions: mask |= MeshModel::MM_VERTCOORD; break;
      case MeshPart::VertexNormals: mask |= MeshModel::MM_VERTNORMAL; break;
      case MeshPart::FaceNormals: mask |= MeshModel::MM_FACENORMAL; break;
      case MeshPart::VertexQuality: mask |= MeshModel::MM_VERTQUALITY; break;
      case MeshPart::VertexColor: mask |= MeshModel::MM_VERTCOLOR; break;
      case MeshPart::FaceQuality: mask |= MeshModel::MM_FACEQUALITY; break;
      case MeshPart::FaceColor: mask |= MeshModel::MM_FACECOLOR; break;
      case MeshPart::WedgeTexCoord: mask |= MeshModel::MM_WEDGTEXCOORD; break;
    }
  return mask;
}

// Adds the filter's parameters for mesh m to `list`, in table order (addParam stores a copy).
inline void add_parameters(const FilterSpec& f, const CMeshO& m, RichParameterList& list) {
  for (const ParamSpec& p : f.parameters(m)) {
    const QString name = qs(p.name), label = qs(p.label), tip = qs(p.tooltip);
    switch (p.kind) {
      case ParamKind::Float:
        list.addParam(RichFloat(name, static_cast<Scalarm>(p.value), label, tip));
        break;
      case ParamKind::Int: list.addParam(RichInt(name, static_cast<int>(p.value), label, tip)); break;
      case ParamKind::Bool: list.addParam(RichBool(name, p.value != 0, label, tip)); break;
      case ParamKind::Enum: {
        QStringList items;
        for (const std::string& item : p.items) items << qs(item);
        list.addParam(RichEnum(name, static_cast<int>(p.value), items, label, tip));
        break;
      }
      case ParamKind::SaveFile:
        list.addParam(RichSaveFileParameter(name, QString(), qs(p.extension), label, tip));
        break;
    }
  }
}

// The user's values by name, for the parameters present in `params`.
inline ParamValues read_values(const FilterSpec& f, const CMeshO& m,
                               const RichParameterList& params) {
  ParamValues values;
  for (const ParamSpec& p : f.parameters(m)) {
    const QString name = qs(p.name);
    if (!params.hasParameter(name)) continue;
    switch (p.kind) {
      case ParamKind::Float: values[p.name] = static_cast<double>(params.getFloat(name)); break;
      case ParamKind::Int: values[p.name] = static_cast<double>(params.getInt(name)); break;
      case ParamKind::Bool: values[p.name] = params.getBool(name) ? 1.0 : 0.0; break;
      case ParamKind::Enum: values[p.name] = static_cast<double>(params.getEnum(name)); break;
      case ParamKind::SaveFile: values[p.name] = params.getSaveFileName(name).toStdString(); break;
    }
  }
  return values;
}

}  // namespace qdml
