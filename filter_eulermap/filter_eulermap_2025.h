// The MeshLab 2025.07 and 2022.02 flavours of the filter: FilterPlugin
// (common/plugins/interfaces/filter_plugin.h of Debian's meshlab 2025.07~dfsg and
// 2022.02+dfsg1, the same interface), as PyPI's pymeshlab 2025.7.post1 loads it with
// pymeshlab.load_plugin() and the MeshLab 2022.02 and 2025.07 GUIs from their plugin
// folders. Only the talk with MeshLab lives here: declaring the parameters from
// parameters.h as RichParameters, reading them back, the document's layers by id, progress,
// log, errors as MLException and the report's figures as return values. The work is
// run_on_layers.h's.
#pragma once

#include <common/plugins/interfaces/filter_plugin.h>

class FilterEulermapPlugin : public QObject, public FilterPlugin {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(FILTER_PLUGIN_IID)
  Q_INTERFACES(FilterPlugin)

 public:
  enum { FP_EULERIAN_MAP };

  FilterEulermapPlugin();

  // The ActionIDType overloads below would hide the QAction ones.
  using FilterPlugin::filterInfo;
  using FilterPlugin::filterName;
  using FilterPlugin::pythonFilterName;

  QString pluginName() const override;
  QString filterName(ActionIDType filter) const override;
  QString pythonFilterName(ActionIDType filter) const override;
  QString filterInfo(ActionIDType filter) const override;
  FilterClass getClass(const QAction *) const override;
  FilterArity filterArity(const QAction *) const override;
  int getPreConditions(const QAction *) const override;
  int postCondition(const QAction *) const override;
  RichParameterList initParameterList(const QAction *, const MeshDocument &md) override;
  std::map<std::string, QVariant> applyFilter(const QAction *, const RichParameterList &parameters, MeshDocument &md,
                                              unsigned int &postConditionMask, vcg::CallBackPos *cb) override;
};
