// MeshLab 2025.07 FilterPlugin of the quasi-developable approximation (see the header).
#include "filter_plugin_2025.h"

#include <algorithm>
#include <vector>

#include "quasidev_adapter.h"

namespace {

QString qs(const std::string& s) { return QString::fromStdString(s); }

// Adds the RichParameter of one row of the shared parameter table.
void add_parameter(RichParameterList& list, const qdml::ParamSpec& p) {
  const QString name = qs(p.name), label = qs(p.label), tip = qs(p.tooltip);
  switch (p.kind) {
    case qdml::ParamKind::Float:
      list.addParam(RichFloat(name, static_cast<Scalarm>(p.value), label, tip));
      return;
    case qdml::ParamKind::Int:
      list.addParam(RichInt(name, static_cast<int>(p.value), label, tip));
      return;
    case qdml::ParamKind::Bool:
      list.addParam(RichBool(name, p.value != 0, label, tip));
      return;
    case qdml::ParamKind::Enum: {
      QStringList items;
      for (const std::string& item : p.items) items << qs(item);
      list.addParam(RichEnum(name, static_cast<int>(p.value), items, label, tip));
      return;
    }
  }
}

// The user's values, by name, in the adapter's encoding (floats, ints, 0/1, enum indices).
std::map<std::string, double> read_values(const std::vector<qdml::ParamSpec>& specs,
                                          const RichParameterList& params) {
  std::map<std::string, double> values;
  for (const qdml::ParamSpec& p : specs) {
    const QString name = qs(p.name);
    if (!params.hasParameter(name)) continue;
    switch (p.kind) {
      case qdml::ParamKind::Float: values[p.name] = static_cast<double>(params.getFloat(name)); break;
      case qdml::ParamKind::Int: values[p.name] = params.getInt(name); break;
      case qdml::ParamKind::Bool: values[p.name] = params.getBool(name) ? 1.0 : 0.0; break;
      case qdml::ParamKind::Enum: values[p.name] = params.getEnum(name); break;
    }
  }
  return values;
}

// A per-patch list as a numpy array in pymeshlab's dict.
template <typename Field>
QVariant patch_list(const std::vector<qd::PatchReport>& patches, Field field) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(patches.size()));
  for (size_t i = 0; i < patches.size(); ++i)
    v[static_cast<Eigen::Index>(i)] = static_cast<double>(field(patches[i]));
  return QVariant::fromValue(v);
}

// The developability term a patch used, as the index of that value of the parameter
// "developability" (curve 0, defect 1, both 2); -1 when the patch was left unchanged.
int developability_code(const qd::PatchReport& p) {
  const std::string& d = p.developability;
  return d == "curve" ? 0 : d == "defect" ? 1 : d == "both" ? 2 : -1;
}

// The figures pymeshlab hands back as a dict. Totals are over the whole mesh; percentages as in
// Eqs. (19)-(20) between the input and the result; lengths in model units and in AE. pymeshlab
// 2025.07 drops string values, so the warnings are counted here; their text is in the log.
std::map<std::string, QVariant> figures_dict(const qd::Result& r) {
  const qd::Figures& before = r.total_before;
  const qd::Figures& after = r.total_after;
  int iterations = 0;
  for (const qd::PatchReport& p : r.patches) iterations = std::max(iterations, p.iterations);
  // Eq. (20) over the whole run; both OBDs are measured against the initial targets.
  const double obd_reduction = before.obd > 0 ? 100.0 * (before.obd - after.obd) / before.obd : 0.0;
  const double ae = r.average_edge;
  using P = qd::PatchReport;
  return {
      {"abd_reduction", r.abd_reduction},
      {"obd_reduction", obd_reduction},
      {"max_abs_k_before", before.max_abs_k},
      {"max_abs_k_after", after.max_abs_k},
      {"angle_defect_before", before.angle_defect},
      {"angle_defect_after", after.angle_defect},
      {"max_displacement", after.max_disp},
      {"max_displacement_ae", after.max_disp / ae},
      {"mean_displacement", after.mean_disp},
      {"mean_displacement_ae", after.mean_disp / ae},
      {"average_edge", ae},
      {"iterations", iterations},
      {"factorizations", r.factorizations},
      {"patches", static_cast<int>(r.patches.size())},
      {"warnings", static_cast<int>(r.warnings.size())},
      {"time_ms", r.time_ms},
      {"patch_id", patch_list(r.patches, [](const P& p) { return p.id; })},
      {"patch_faces", patch_list(r.patches, [](const P& p) { return p.faces; })},
      {"patch_iterations", patch_list(r.patches, [](const P& p) { return p.iterations; })},
      {"patch_abd_reduction", patch_list(r.patches, [](const P& p) { return p.abd_reduction; })},
      {"patch_obd_reduction", patch_list(r.patches, [](const P& p) { return p.obd_reduction; })},
      {"patch_fit_residual_deg", patch_list(r.patches, [](const P& p) { return p.fit_residual_deg; })},
      {"patch_developability", patch_list(r.patches, developability_code)},
      {"patch_max_displacement", patch_list(r.patches, [](const P& p) { return p.after.max_disp; })},
      {"patch_max_abs_k_after", patch_list(r.patches, [](const P& p) { return p.after.max_abs_k; })},
  };
}

}  // namespace

QuasiDevFilterPlugin::QuasiDevFilterPlugin() {
  typeList = {FP_QUASI_DEVELOPABLE};
  for (ActionIDType id : typeList) actionList.push_back(new QAction(filterName(id), this));
}

QString QuasiDevFilterPlugin::pluginName() const { return "FilterQuasiDevelopable"; }

QString QuasiDevFilterPlugin::vendor() const { return "filter_quasidev"; }

QString QuasiDevFilterPlugin::filterName(ActionIDType filter) const {
  if (filter != FP_QUASI_DEVELOPABLE) return QString();
  return qs(qdml::filter_name());
}

QString QuasiDevFilterPlugin::pythonFilterName(ActionIDType filter) const {
  if (filter != FP_QUASI_DEVELOPABLE) return QString();
  return qs(qdml::python_filter_name());
}

QString QuasiDevFilterPlugin::filterInfo(ActionIDType filter) const {
  if (filter != FP_QUASI_DEVELOPABLE) return QString();
  return qs(qdml::filter_info());
}

FilterPlugin::FilterClass QuasiDevFilterPlugin::getClass(const QAction*) const {
  return FilterClass(Smoothing | Quality | VertexColoring);
}

FilterPlugin::FilterArity QuasiDevFilterPlugin::filterArity(const QAction*) const {
  return SINGLE_MESH;
}

int QuasiDevFilterPlugin::postCondition(const QAction*) const {
  return MeshModel::MM_VERTCOORD | MeshModel::MM_VERTNORMAL | MeshModel::MM_FACENORMAL |
         MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR;
}

RichParameterList QuasiDevFilterPlugin::initParameterList(const QAction*, const MeshModel& m) {
  RichParameterList list;
  for (const qdml::ParamSpec& p : qdml::parameter_specs(m.cm)) add_parameter(list, p);
  return list;
}

std::map<std::string, QVariant> QuasiDevFilterPlugin::applyFilter(
    const QAction* action, const RichParameterList& params, MeshDocument& md,
    unsigned int& /*postConditionMask: postCondition() applies*/, vcg::CallBackPos* cb) {
  if (ID(action) != FP_QUASI_DEVELOPABLE) wrongActionCalled(action);
  MeshModel* mm = md.mm();
  if (mm == nullptr)
    throw MLException("Quasi-Developable Approximation: no current mesh; load a mesh first.");
  const qdml::Settings settings =
      qdml::settings_from_values(read_values(qdml::parameter_specs(mm->cm), params));
  const bool has_face_quality = mm->hasDataMask(MeshModel::MM_FACEQUALITY);
  const qdml::Outcome outcome = qdml::apply(mm->cm, has_face_quality, settings, cb);
  for (const std::string& line : outcome.log) log(line);
  if (!outcome.ok) throw MLException(qs(outcome.error));
  mm->updateDataMask(MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR);
  return figures_dict(outcome.result);
}

MESHLAB_PLUGIN_NAME_EXPORTER(QuasiDevFilterPlugin)
