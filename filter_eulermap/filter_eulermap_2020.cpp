#include "filter_eulermap_2020.h"

#include "run_on_layers.h"

using namespace eulermap::plugin;

namespace {

// The document's layers, numbered by their position (as .mlx scripts and RichMesh do).
LayerDocument<MeshModel> Layers(MeshDocument &md) {
  LayerDocument<MeshModel> doc;
  for (int i = 0; i < md.size(); ++i) doc.layers.push_back(i);
  doc.layer = [&md](int i) { return md.meshList.at(i); };
  doc.add = [&md](const QString &label) { return md.addNewMesh("", label, false); };
  return doc;
}

}  // namespace

FilterEulermapPlugin::FilterEulermapPlugin() {
  typeList << FP_EULERIAN_MAP;
  for (FilterIDType t : types()) actionList << new QAction(filterName(t), this);
}

QString FilterEulermapPlugin::pluginName() const { return "FilterEulermap"; }

QString FilterEulermapPlugin::filterName(FilterIDType) const { return FilterName(); }

QString FilterEulermapPlugin::filterInfo(FilterIDType) const { return FilterDescription(); }

// Remeshing: the filter makes new meshes whose connectivity and topology differ from
// both inputs (the cut source) and a remesh of the target with the source's
// connectivity (the mapped layer); texture transfer is optional and secondary.
MeshFilterInterface::FilterClass FilterEulermapPlugin::getClass(QAction *) { return MeshFilterInterface::Remeshing; }

// Two layers, chosen by the source_mesh / target_mesh parameters.
MeshFilterInterface::FILTER_ARITY FilterEulermapPlugin::filterArity(QAction *) const { return FIXED; }

int FilterEulermapPlugin::getPreConditions(QAction *) const { return MeshModel::MM_NONE; }

// The input layers are not changed; the results are new layers.
int FilterEulermapPlugin::postCondition(QAction *) const { return MeshModel::MM_NONE; }

void FilterEulermapPlugin::initParameterSet(QAction *, MeshDocument &md, RichParameterList &parameters) {
  const LayerDocument<MeshModel> layers = Layers(md);
  MeshModel *current = md.mm();
  MeshModel *other = current ? layers.layer(DefaultTargetLayer(md.meshList.indexOf(current), layers.layers)) : nullptr;
  MeshDocument *doc = current ? &md : nullptr;  // RichMesh asserts on a layer not in the document
  for (const ParameterSpec &p : Parameters()) {
    switch (p.kind) {
    case ParameterKind::Mesh:
      parameters.addParam(RichMesh(p.name, p.name == param::kSourceMesh ? current : other, doc, p.label, p.help));
      break;
    case ParameterKind::Int:
      parameters.addParam(RichInt(p.name, p.defaultValue.toInt(), p.label, p.help));
      break;
    case ParameterKind::Float:
      parameters.addParam(RichFloat(p.name, p.defaultValue.toFloat(), p.label, p.help));
      break;
    case ParameterKind::Enum:
      parameters.addParam(RichEnum(p.name, p.defaultValue.toInt(), p.choices, p.label, p.help));
      break;
    case ParameterKind::Bool:
      parameters.addParam(RichBool(p.name, p.defaultValue.toBool(), p.label, p.help));
      break;
    case ParameterKind::OpenFile:
      parameters.addParam(RichOpenFile(p.name, p.defaultValue.toString(), p.choices, p.label, p.help));
      break;
    case ParameterKind::String:
      parameters.addParam(RichString(p.name, p.defaultValue.toString(), p.label, p.help));
      break;
    }
  }
}

bool FilterEulermapPlugin::applyFilter(QAction *, MeshDocument &md, const RichParameterList &parameters,
                                       vcg::CallBackPos *cb) {
  const Request request = ReadRequest([&](const ParameterSpec &p) -> QVariant {
    switch (p.kind) {
    case ParameterKind::Mesh: return md.meshList.indexOf(parameters.getMesh(p.name));
    case ParameterKind::Int: return parameters.getInt(p.name);
    case ParameterKind::Float: return double(parameters.getFloat(p.name));
    case ParameterKind::Enum: return parameters.getEnum(p.name);
    case ParameterKind::Bool: return parameters.getBool(p.name);
    case ParameterKind::OpenFile: return parameters.getOpenFileName(p.name);
    case ParameterKind::String: return parameters.getString(p.name);
    }
    return {};
  });
  auto log = [this](const QString &line) { Log(GLLogStream::FILTER, line.toStdString()); };
  eulermap::Result result;
  QString error;
  if (RunOnLayers(request, Layers(md), MeshLabProgress(cb), log, result, error)) return true;
  // meshlabserver prints the log but not errorMessage: say it in both.
  errorMessage = error;
  Log(GLLogStream::WARNING, ("Eulerian Surface Map failed: " + error).toStdString());
  return false;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterEulermapPlugin)
