// The MeshLab 2025.07 face of the plugin (FilterPlugin API), built twice: double / "2025.07d"
// for pymeshlab 2025.7.post1 and float / "2025.07" for the MeshLab 2025.07 application. One
// filter per entry of qdml::filter_table() (its index is the filter id); all filter logic lives
// in the shared adapter. This class only
//   in:  maps the entry's declared parameters to a RichParameterList and reads them back by name;
//   out: logs the run's lines, throws MLException with its message on failure, and returns its
//        figures as std::map<std::string, QVariant> (pymeshlab: a dict).
#pragma once

#include <common/plugins/interfaces/filter_plugin.h>

#include <map>
#include <string>

class QuasiDevFilterPlugin : public QObject, public FilterPlugin {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(FILTER_PLUGIN_IID)
  Q_INTERFACES(FilterPlugin)

 public:
  QuasiDevFilterPlugin();

  QString pluginName() const override;
  QString vendor() const override;
  QString filterName(ActionIDType filter) const override;
  QString pythonFilterName(ActionIDType filter) const override;
  QString filterInfo(ActionIDType filter) const override;
  FilterClass getClass(const QAction* action) const override;
  FilterArity filterArity(const QAction* action) const override;
  int postCondition(const QAction* action) const override;

  // The entry's parameters for m: same names, order, types and defaults as 2020.09.
  RichParameterList initParameterList(const QAction* action, const MeshModel& m) override;

  // Runs the entry on the current mesh. Throws MLException (the run's message) on failure, the
  // mesh then unchanged; returns the run's figures on success.
  std::map<std::string, QVariant> applyFilter(const QAction* action,
                                              const RichParameterList& params, MeshDocument& md,
                                              unsigned int& postConditionMask,
                                              vcg::CallBackPos* cb) override;
};
