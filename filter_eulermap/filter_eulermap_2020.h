// The MeshLab 2020.09 flavour of the filter: MeshFilterInterface (common/interfaces.h of
// Debian's meshlab 2020.09+dfsg1). Only the talk with MeshLab lives here: declaring the
// parameters from parameters.h as RichParameters, reading them back, copying layers in
// and out (mesh_convert.h), progress and log. The work is map_layers.h's.
#pragma once

#include <common/interfaces.h>

class FilterEulermapPlugin : public QObject, public MeshFilterInterface {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
  Q_INTERFACES(MeshFilterInterface)

 public:
  enum { FP_EULERIAN_MAP };

  FilterEulermapPlugin();

  QString pluginName() const override;
  QString filterName(FilterIDType filter) const override;
  QString filterInfo(FilterIDType filter) const override;
  FilterClass getClass(QAction *) override;
  FILTER_ARITY filterArity(QAction *) const override;
  int getPreConditions(QAction *) const override;
  int postCondition(QAction *) const override;
  using MeshFilterInterface::initParameterSet;
  void initParameterSet(QAction *, MeshDocument &md, RichParameterList &parameters) override;
  bool applyFilter(QAction *, MeshDocument &md, const RichParameterList &parameters, vcg::CallBackPos *cb) override;
};
