#include "filter_plugin_2020.h"

#include <string>

#include "plugin_table.h"

namespace {

// The table entry of an action of this plugin (ID() asserts on a foreign action).
const qdml::FilterSpec& spec(const MeshFilterInterface& plugin, QAction* action) {
  return qdml::filter_table().at(static_cast<std::size_t>(plugin.ID(action)));
}

}  // namespace

QuasiDevFilterPlugin::QuasiDevFilterPlugin() {
  for (std::size_t id = 0; id < qdml::filter_table().size(); ++id)
    typeList << static_cast<FilterIDType>(id);
  for (FilterIDType id : typeList) actionList << new QAction(filterName(id), this);
}

QString QuasiDevFilterPlugin::pluginName() const { return "FilterQuasiDev"; }

QString QuasiDevFilterPlugin::filterName(FilterIDType filter) const {
  return qdml::filter_text(filter, &qdml::FilterSpec::name);
}

QString QuasiDevFilterPlugin::filterInfo(FilterIDType filter) const {
  return qdml::filter_text(filter, &qdml::FilterSpec::info);
}

MeshFilterInterface::FilterClass QuasiDevFilterPlugin::getClass(QAction* action) {
  return qdml::filter_class<MeshFilterInterface>(spec(*this, action));
}

MeshFilterInterface::FILTER_ARITY QuasiDevFilterPlugin::filterArity(QAction*) const {
  return SINGLE_MESH;
}

int QuasiDevFilterPlugin::postCondition(QAction* action) const {
  return qdml::mesh_mask(spec(*this, action).changes);
}

void QuasiDevFilterPlugin::initParameterSet(QAction* action, MeshModel& m, RichParameterList& par) {
  qdml::add_parameters(spec(*this, action), m.cm, par);
}

bool QuasiDevFilterPlugin::applyFilter(QAction* action, MeshDocument& md,
                                       const RichParameterList& par, vcg::CallBackPos* cb) {
  const qdml::FilterSpec& f = spec(*this, action);
  MeshModel& mm = *md.mm();
  const qdml::FilterRun run =
      f.run(mm.cm, mm.hasDataMask(MeshModel::MM_FACEQUALITY), qdml::read_values(f, mm.cm, par), cb);
  for (const std::string& line : run.log) Log(line);
  if (!run.ok) {
    errorMessage = qdml::qs(f.name + " failed: " + run.error);
    Log(errorMessage.toStdString());
    return false;
  }
  mm.updateDataMask(qdml::mesh_mask(run.written));
  return true;
}

MESHLAB_PLUGIN_NAME_EXPORTER(QuasiDevFilterPlugin)
