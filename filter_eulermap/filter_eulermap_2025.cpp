#include "filter_eulermap_2025.h"

#include "rich_parameters.h"
#include "run_on_layers.h"

#include <common/mlexception.h>

// MeshLab 2022.02 names the open-file parameter RichOpenFile (common/parameters/rich_parameter.h);
// 2025.07 renamed it RichFileOpen, with the same arguments, in a header of its own. The rest of
// the FilterPlugin interface this shim uses is the same in both.
#if __has_include(<common/parameters/rich_parameter/rich_file_open.h>)
using OpenFileParameter = RichFileOpen;
#else
using OpenFileParameter = RichOpenFile;
#endif

#include <algorithm>

using namespace eulermap::plugin;

namespace {

// The document's layers, numbered by their id (pymeshlab's and 2025.07's RichMesh numbers;
// pymeshlab passes any integer through, so a number may name no layer: CheckLayerChoice
// says so before any is used).
std::vector<int> LayerIds(const MeshDocument &md) {
  std::vector<int> ids;
  for (const MeshModel &m : md.meshIterator()) ids.push_back(m.id());
  return ids;
}

LayerDocument<MeshModel> Layers(MeshDocument &md) {
  LayerDocument<MeshModel> doc;
  doc.layers = LayerIds(md);
  doc.layer = [&md](int id) { return md.getMesh(id); };
  doc.add = [&md](const QString &label) { return md.addNewMesh("", label, false); };
  // 2025.07 layers hold their texture images: the new layer needs them to be saved and
  // shown with its textures.
  doc.copyTextureImages = [](MeshModel &to, const MeshModel &from) {
    for (const std::string &name : to.cm.textures)
      if (from.getTextures().count(name) && !to.getTextures().count(name)) to.addTexture(name, from.getTexture(name));
  };
  return doc;
}

}  // namespace

FilterEulermapPlugin::FilterEulermapPlugin() {
  typeList = {FP_EULERIAN_MAP};
  // FilterPlugin::ID() finds an action's filter by its text: it must be the filter's name.
  for (ActionIDType t : types()) actionList.push_back(new QAction(filterName(t), this));
}

QString FilterEulermapPlugin::pluginName() const { return "FilterEulermap"; }

QString FilterEulermapPlugin::filterName(ActionIDType) const { return FilterName(); }

// pymeshlab's name, in its verb_object style (the name derived from the menu name would
// be eulerian_surface_map).
QString FilterEulermapPlugin::pythonFilterName(ActionIDType) const { return "generate_eulerian_surface_map"; }

QString FilterEulermapPlugin::filterInfo(ActionIDType) const { return FilterDescription(); }

// Remeshing, as in the 2020.09 flavour: new meshes whose connectivity and topology differ
// from the inputs'. (pymeshlab refuses a plugin with a Generic filter.)
FilterPlugin::FilterClass FilterEulermapPlugin::getClass(const QAction *) const { return FilterPlugin::Remeshing; }

// Two layers, chosen by the source_mesh / target_mesh parameters.
FilterPlugin::FilterArity FilterEulermapPlugin::filterArity(const QAction *) const { return FilterPlugin::FIXED; }

int FilterEulermapPlugin::getPreConditions(const QAction *) const { return MeshModel::MM_NONE; }

// The input layers are not changed; the results are new layers.
int FilterEulermapPlugin::postCondition(const QAction *) const { return MeshModel::MM_NONE; }

RichParameterList FilterEulermapPlugin::initParameterList(const QAction *, const MeshDocument &md) {
  const std::vector<int> layers = LayerIds(md);
  const int current = md.mm() ? md.mm()->id() : 0;
  RichParameterList parameters;
  DeclareParameters(
      parameters,
      [&](const eulermap::Parameter &p) {
        return RichMesh(Name(p), Name(p) == eulermap::parameter::kSourceMesh ? current : DefaultTargetLayer(current, layers), &md,
                        Label(p), Help(p));
      },
      [](const eulermap::Parameter &p) { return OpenFileParameter(Name(p), QString(), Choices(p), Label(p), Help(p)); });
  return parameters;
}

std::map<std::string, QVariant> FilterEulermapPlugin::applyFilter(const QAction *, const RichParameterList &parameters,
                                                                  MeshDocument &md, unsigned int &,
                                                                  vcg::CallBackPos *cb) {
  const Request request = ReadParameters(parameters, [&](const eulermap::Parameter &p) { return int(parameters.getMeshId(Name(p))); });
  auto log = [this](const QString &line) { this->log(GLLogStream::FILTER, line.toStdString()); };
  eulermap::Result result;
  QString error;
  const LayerDocument<MeshModel> layers = Layers(md);
  if (!RunOnLayers(request, layers, MeshLabProgress(cb), log, result, error)) {
    // pymeshlab 2025.7.post1 gives the plugin its MeshSet's log before applyFilter and takes
    // it back only when applyFilter returns (helpers/meshset_helper.cpp): after a throw the
    // plugin would go on logging into a MeshSet that Python may have freed. Drop it here.
    setLog(nullptr);
    // Reported as PyMeshLabException "Failed to apply filter: ...\nDetails: <message>".
    throw MLException(error);
  }
  return ReportFigures(result.report);
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterEulermapPlugin)
