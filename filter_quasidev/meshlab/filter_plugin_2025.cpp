// MeshLab 2025.07 FilterPlugin over the shared filter table (see the header).
#include "filter_plugin_2025.h"

#include <Eigen/Core>
#include <type_traits>
#include <vector>

#include "plugin_table.h"

namespace {

// A figure as pymeshlab hands it back: int, float, or a numpy array for a per-patch list.
QVariant variant(const qdml::Figure& figure) {
  return std::visit(
      [](const auto& value) {
        using T = std::decay_t<decltype(value)>;
        if constexpr (std::is_same_v<T, std::vector<double>>) {
          const Eigen::VectorXd v = Eigen::Map<const Eigen::VectorXd>(
              value.data(), static_cast<Eigen::Index>(value.size()));
          return QVariant::fromValue(v);
        } else {
          return QVariant(value);
        }
      },
      figure);
}

// The table entry of an action of this plugin; a foreign action throws (wrongActionCalled).
const qdml::FilterSpec& spec(const FilterPlugin& plugin, const QAction* action) {
  const qdml::FilterSpec* f = qdml::filter_spec(plugin.ID(action));
  if (f == nullptr) FilterPlugin::wrongActionCalled(action);
  return *f;
}

}  // namespace

QuasiDevFilterPlugin::QuasiDevFilterPlugin() {
  for (std::size_t id = 0; id < qdml::filter_table().size(); ++id)
    typeList.push_back(static_cast<ActionIDType>(id));
  for (ActionIDType id : typeList) actionList.push_back(new QAction(filterName(id), this));
}

QString QuasiDevFilterPlugin::pluginName() const { return "FilterQuasiDevelopable"; }

QString QuasiDevFilterPlugin::vendor() const { return "filter_quasidev"; }

QString QuasiDevFilterPlugin::filterName(ActionIDType filter) const {
  return qdml::filter_text(filter, &qdml::FilterSpec::name);
}

QString QuasiDevFilterPlugin::pythonFilterName(ActionIDType filter) const {
  return qdml::filter_text(filter, &qdml::FilterSpec::python_name);
}

QString QuasiDevFilterPlugin::filterInfo(ActionIDType filter) const {
  return qdml::filter_text(filter, &qdml::FilterSpec::info);
}

FilterPlugin::FilterClass QuasiDevFilterPlugin::getClass(const QAction* action) const {
  return qdml::filter_class<FilterPlugin>(spec(*this, action));
}

FilterPlugin::FilterArity QuasiDevFilterPlugin::filterArity(const QAction*) const {
  return SINGLE_MESH;
}

int QuasiDevFilterPlugin::postCondition(const QAction* action) const {
  return qdml::mesh_mask(spec(*this, action).changes);
}

RichParameterList QuasiDevFilterPlugin::initParameterList(const QAction* action,
                                                          const MeshModel& m) {
  RichParameterList list;
  qdml::add_parameters(spec(*this, action), m.cm, list);
  return list;
}

std::map<std::string, QVariant> QuasiDevFilterPlugin::applyFilter(
    const QAction* action, const RichParameterList& params, MeshDocument& md,
    unsigned int& /*postConditionMask: postCondition() applies*/, vcg::CallBackPos* cb) {
  const qdml::FilterSpec& f = spec(*this, action);
  MeshModel* mm = md.mm();
  if (mm == nullptr) throw MLException(qdml::qs(f.name + ": no current mesh; load a mesh first."));
  const qdml::FilterRun run = f.run(mm->cm, mm->hasDataMask(MeshModel::MM_FACEQUALITY),
                                    qdml::read_values(f, mm->cm, params), cb);
  for (const std::string& line : run.log) log(line);
  if (!run.ok) throw MLException(qdml::qs(run.error));
  // Declares all the filter may change (its post-condition), written this time or not, as this
  // plugin always has (2020.09 declares what the run wrote).
  mm->updateDataMask(qdml::mesh_mask(f.changes));
  std::map<std::string, QVariant> figures;
  for (const auto& [name, figure] : run.figures) figures[name] = variant(figure);
  return figures;
}

MESHLAB_PLUGIN_NAME_EXPORTER(QuasiDevFilterPlugin)
