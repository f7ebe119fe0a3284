// The MeshLab 2020.09 filter plugin (MeshFilterInterface): one filter per entry of
// qdml::filter_table() (its index is the filter id), parameters mapped to RichParameterList,
// the entry's run on the current mesh, logging with Log() and failures reported through
// errorMessage (after logging the reason: meshlabserver 2020.09 prints only "Problem with
// filter").
#pragma once

#include <common/interfaces.h>

class QuasiDevFilterPlugin : public QObject, public MeshFilterInterface {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
  Q_INTERFACES(MeshFilterInterface)

 public:
  QuasiDevFilterPlugin();
  QString pluginName() const override;
  QString filterName(FilterIDType filter) const override;
  QString filterInfo(FilterIDType filter) const override;
  FilterClass getClass(QAction* action) override;
  FILTER_ARITY filterArity(QAction* action) const override;
  int postCondition(QAction* action) const override;
  void initParameterSet(QAction* action, MeshModel& m, RichParameterList& par) override;
  bool applyFilter(QAction* action, MeshDocument& md, const RichParameterList& par,
                   vcg::CallBackPos* cb) override;
};
