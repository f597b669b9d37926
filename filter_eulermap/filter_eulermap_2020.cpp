#include "filter_eulermap_2020.h"

#include "map_layers.h"

using namespace eulermap::plugin;

namespace {

void ToInput(MeshModel &m, InputLayer &layer) {
  layer.label = m.label();
  layer.fileName = m.fullName();
  layer.has.vertexTexCoords = m.hasDataMask(MeshModel::MM_VERTTEXCOORD);
  layer.has.wedgeTexCoords = m.hasDataMask(MeshModel::MM_WEDGTEXCOORD);
  LayerToCore(m.cm, layer.has, layer.mesh);
}

// A new layer holding `mesh`; with `targetPositions`, their vertices become its
// per-vertex attribute "TargetPosition". The current layer stays as it is.
MeshModel *AddLayer(MeshDocument &md, const QString &label, const eulermap::Mesh &mesh, const LayerComponents &has,
                    const eulermap::Mesh *targetPositions) {
  MeshModel *m = md.addNewMesh("", label, false);
  int mask = MeshModel::MM_VERTQUALITY;
  if (has.wedgeTexCoords) mask |= MeshModel::MM_WEDGTEXCOORD;
  if (has.vertexTexCoords) mask |= MeshModel::MM_VERTTEXCOORD;
  m->updateDataMask(mask);
  CoreToLayer(mesh, has, m->cm);
  if (targetPositions) {
    auto target = vcg::tri::Allocator<CMeshO>::GetPerVertexAttribute<Point3m>(m->cm, "TargetPosition");
    size_t i = 0;
    for (const eulermap::Vertex &v : targetPositions->vert)
      if (!v.IsD() && i < m->cm.vert.size()) target[m->cm.vert[i++]].Import(v.cP());
  }
  return m;
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
  MeshModel *current = md.mm();
  MeshModel *other = current;
  for (MeshModel *m : md.meshList)
    if (m != current) {
      other = m;
      break;
    }
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
  // meshlabserver prints the log but not errorMessage: say it in both.
  auto fail = [&](const QString &message) {
    errorMessage = message;
    Log(GLLogStream::WARNING, ("Eulerian Surface Map failed: " + message).toStdString());
    return false;
  };
  int lastPercent = -1;
  QString lastStage;
  const ProgressFn progress = [&](int percent, const QString &stage) {
    if (!cb || (percent == lastPercent && stage == lastStage)) return true;
    lastPercent = percent;
    lastStage = stage;
    return cb(percent, qUtf8Printable(stage));
  };

  QString error;
  if (!CheckLayerChoice(request, md.size(), error)) return fail(error);
  progress(0, "Eulerian map: copying layers");
  InputLayer source, target;
  ToInput(*md.meshList.at(request.sourceLayer), source);
  ToInput(*md.meshList.at(request.targetLayer), target);

  eulermap::Result result;
  QStringList lines;
  const bool ok = MapLayers(request, source, target, progress, result, lines, error);
  for (const QString &line : lines) log(line);
  if (!ok) return fail(error);

  progress(kProgressCoreEnd, "Eulerian map: making layers");
  const LayerComponents out = OutputComponents(request, source, target);
  const QString cut = OutputLabel(source.label, "cut"), mapped = OutputLabel(source.label, "mapped");
  log(LayerLine(AddLayer(md, cut, result.cut, out, &result.mapped)->label(), result.cut));
  log(LayerLine(AddLayer(md, mapped, result.mapped, out, nullptr)->label(), result.mapped));
  if (request.options.fillHoles) {
    const QString filled = OutputLabel(source.label, "filled");
    if (result.filled.FN() > 0)
      log(LayerLine(AddLayer(md, filled, result.filled, out, nullptr)->label(), result.filled));
    else
      log("warning: fill_holes gave no faces, so no " + filled + " layer was made");
  }
  progress(100, "Eulerian map: done");
  return true;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterEulermapPlugin)
