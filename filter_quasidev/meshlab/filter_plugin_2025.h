// The MeshLab 2025.07 face of the quasi-developable approximation (FilterPlugin API), built twice:
// double / "2025.07d" for pymeshlab 2025.7.post1 and float / "2025.07" for the MeshLab 2025.07
// application. All filter logic lives in the shared adapter (quasidev_adapter.h); this class only
//   in:  maps the adapter's ParamSpec table to a RichParameterList and reads it back by name;
//   out: logs the adapter's lines, throws MLException with the adapter's message on failure, and
//        returns the engine's figures as std::map<std::string, QVariant> (pymeshlab: a dict).
#pragma once

#include <map>
#include <string>

#include <common/plugins/interfaces/filter_plugin.h>

class QuasiDevFilterPlugin : public QObject, public FilterPlugin {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(FILTER_PLUGIN_IID)
  Q_INTERFACES(FilterPlugin)

 public:
  enum { FP_QUASI_DEVELOPABLE };

  QuasiDevFilterPlugin();

  QString pluginName() const override;
  QString vendor() const override;
  QString filterName(ActionIDType filter) const override;
  QString pythonFilterName(ActionIDType filter) const override;
  QString filterInfo(ActionIDType filter) const override;
  FilterClass getClass(const QAction* action) const override;
  FilterArity filterArity(const QAction* action) const override;
  int postCondition(const QAction* action) const override;

  // Parameters from qdml::parameter_specs(m): same names, order, types and defaults as 2020.09.
  RichParameterList initParameterList(const QAction* action, const MeshModel& m) override;

  // Runs qdml::apply on the current mesh. Throws MLException (the adapter's message) on failure,
  // the mesh then unchanged; returns the figures (see figures_dict in the .cpp) on success.
  std::map<std::string, QVariant> applyFilter(const QAction* action,
                                              const RichParameterList& params, MeshDocument& md,
                                              unsigned int& postConditionMask,
                                              vcg::CallBackPos* cb) override;
};
