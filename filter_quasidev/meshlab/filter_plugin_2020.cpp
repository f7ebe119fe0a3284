#include "filter_plugin_2020.h"

#include <map>
#include <memory>
#include <string>

#include "quasidev_adapter.h"

namespace {

QString qstring(const std::string& s) { return QString::fromStdString(s); }

QStringList qstring_list(const std::vector<std::string>& items) {
  QStringList list;
  for (const std::string& item : items) list << qstring(item);
  return list;
}

// The RichParameter of one entry of the shared parameter table (addParam stores a clone).
std::unique_ptr<RichParameter> rich_parameter(const qdml::ParamSpec& spec) {
  const QString name = qstring(spec.name);
  const QString label = qstring(spec.label);
  const QString tip = qstring(spec.tooltip);
  switch (spec.kind) {
    case qdml::ParamKind::Int:
      return std::make_unique<RichInt>(name, static_cast<int>(spec.value), label, tip);
    case qdml::ParamKind::Bool:
      return std::make_unique<RichBool>(name, spec.value != 0, label, tip);
    case qdml::ParamKind::Enum:
      return std::make_unique<RichEnum>(name, static_cast<int>(spec.value), qstring_list(spec.items), label,
                          tip);
    case qdml::ParamKind::Float:
      break;
  }
  return std::make_unique<RichFloat>(name, static_cast<float>(spec.value), label, tip);
}

// The value of one parameter as the adapter's number (float, int, 0/1, enum index).
double parameter_value(const RichParameterList& par, const qdml::ParamSpec& spec) {
  const QString name = qstring(spec.name);
  switch (spec.kind) {
    case qdml::ParamKind::Int: return par.getInt(name);
    case qdml::ParamKind::Bool: return par.getBool(name) ? 1.0 : 0.0;
    case qdml::ParamKind::Enum: return par.getEnum(name);
    case qdml::ParamKind::Float: break;
  }
  return static_cast<double>(par.getFloat(name));
}

}  // namespace

QuasiDevFilterPlugin::QuasiDevFilterPlugin() {
  typeList << FP_QUASI_DEVELOPABLE;
  for (FilterIDType id : typeList) actionList << new QAction(filterName(id), this);
}

QString QuasiDevFilterPlugin::pluginName() const { return "FilterQuasiDev"; }

QString QuasiDevFilterPlugin::filterName(FilterIDType) const {
  return qstring(qdml::filter_name());
}

QString QuasiDevFilterPlugin::filterInfo(FilterIDType) const {
  return qstring(qdml::filter_info());
}

MeshFilterInterface::FilterClass QuasiDevFilterPlugin::getClass(QAction*) {
  return FilterClass(Smoothing | Quality | VertexColoring);
}

MeshFilterInterface::FILTER_ARITY QuasiDevFilterPlugin::filterArity(QAction*) const {
  return SINGLE_MESH;
}

int QuasiDevFilterPlugin::postCondition(QAction*) const {
  return MeshModel::MM_VERTCOORD | MeshModel::MM_VERTNORMAL | MeshModel::MM_FACENORMAL |
         MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR;
}

void QuasiDevFilterPlugin::initParameterSet(QAction*, MeshModel& m, RichParameterList& par) {
  for (const qdml::ParamSpec& spec : qdml::parameter_specs(m.cm)) par.addParam(*rich_parameter(spec));
}

bool QuasiDevFilterPlugin::applyFilter(QAction*, MeshDocument& md, const RichParameterList& par,
                                       vcg::CallBackPos* cb) {
  MeshModel& mm = *md.mm();
  std::map<std::string, double> values;
  for (const qdml::ParamSpec& spec : qdml::parameter_specs(mm.cm))
    values[spec.name] = parameter_value(par, spec);
  const qdml::Settings settings = qdml::settings_from_values(values);
  const qdml::Outcome outcome =
      qdml::apply(mm.cm, mm.hasDataMask(MeshModel::MM_FACEQUALITY), settings, cb);
  for (const std::string& line : outcome.log) Log(line);
  if (!outcome.ok) {
    errorMessage = qstring(qdml::filter_name() + " failed: " + outcome.error);
    Log(errorMessage.toStdString());
    return false;
  }
  mm.updateDataMask(settings.colorize ? MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR
                                      : MeshModel::MM_VERTQUALITY);
  return true;
}

MESHLAB_PLUGIN_NAME_EXPORTER(QuasiDevFilterPlugin)
