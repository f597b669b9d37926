#include "map_layers.h"

#include "anchors.h"

#include <QFileInfo>

#include <algorithm>
#include <new>

namespace eulermap::plugin {

namespace {

QStringList Lines(const std::string &text) {
  QStringList lines = QString::fromStdString(text).split('\n');
  while (!lines.isEmpty() && lines.last().trimmed().isEmpty()) lines.removeLast();
  return lines;
}

}  // namespace

bool CheckLayerChoice(const Request &request, const std::vector<int> &layers, QString &error) {
  if (layers.size() < 2 || request.targetLayer < 0) {
    error = "no target mesh: load the surface to map onto as another layer and choose it as target_mesh";
    return false;
  }
  QStringList numbers;
  for (int n : layers) numbers << QString::number(n);
  for (const auto &[name, layer] : {std::pair(parameter::kSourceMesh, request.sourceLayer),
                                    std::pair(parameter::kTargetMesh, request.targetLayer)}) {
    if (std::find(layers.begin(), layers.end(), layer) == layers.end()) {
      error = QString("%1: layer %2 does not exist (the document has layers %3)")
                  .arg(name).arg(layer).arg(numbers.join(", "));
      return false;
    }
  }
  if (request.sourceLayer == request.targetLayer) {
    error = "target_mesh is the source mesh itself: choose another layer as target_mesh (the surface to "
            "map onto)";
    return false;
  }
  return true;
}

int DefaultTargetLayer(int current, const std::vector<int> &layers) {
  for (int n : layers)
    if (n != current) return n;
  return current;
}

bool MapLayers(const Request &request, InputLayer &source, InputLayer &target, const ProgressFn &progress,
               Result &result, QStringList &log, QString &error) {
  log << QString("Eulerian Surface Map: '%1' (%2 vertices, %3 faces) -> '%4' (%5 vertices, %6 faces)")
             .arg(source.label).arg(source.mesh.VN()).arg(source.mesh.FN())
             .arg(target.label).arg(target.mesh.VN()).arg(target.mesh.FN());

  std::vector<AnchorPair> anchors;
  AnchorSettings settings;
  settings.sourceFile = request.sourceAnchors;
  settings.targetFile = request.targetAnchors;
  settings.pairs = request.anchorPairs;
  QStringList notes;
  if (!ResolveAnchors(settings, {source.label, source.fileName, &source.mesh},
                      {target.label, target.fileName, &target.mesh}, anchors, notes, error))
    return false;
  log << notes;

  Options options = request.options;
  options.transferColour = request.options.transferColour && target.has.vertexColours;
  options.transferQuality = request.options.transferQuality && target.has.vertexQuality;
  if (request.options.transferColour && !target.has.vertexColours && !target.has.vertexQuality)
    log << QString("note: transfer_color_quality: the target '%1' has no per-vertex colour or quality, so "
                   "none is transferred").arg(target.label);
  if (request.options.transferTexture && !target.has.wedgeTexCoords && !target.has.vertexTexCoords)
    log << QString("note: transfer_texture: the target '%1' has no texture coordinates, so none are pulled; "
                   "the _cut layer keeps the source's own, if any").arg(target.label);

  const int span = kProgressCoreEnd - kProgressCoreBegin;
  const Progress coreProgress = [&](double share, const std::string &stage) {
    const double s = share < 0 ? 0 : share > 1 ? 1 : share;
    return progress ? progress(kProgressCoreBegin + int(s * span), QString::fromStdString(stage)) : true;
  };
  try {
    ComputeMap(source.mesh, target.mesh, anchors, options, result, coreProgress);
  } catch (const Error &e) {
    error = QString::fromStdString(e.what());
    return false;
  } catch (const std::bad_alloc &) {
    error = QString("out of memory at grid_resolution %1: lower grid_resolution (memory grows with its cube)")
                .arg(request.options.gridResolution);
    return false;
  } catch (const std::exception &e) {
    error = QString("internal error in the map: %1").arg(e.what());
    return false;
  }
  log << Lines(result.report.ToText());
  return true;
}

QString OutputLabel(const QString &sourceLabel, const char *suffix) {
  const QString base = QFileInfo(sourceLabel).completeBaseName();
  return (base.isEmpty() ? sourceLabel : base) + "_" + suffix;
}

OutputLayers OutputComponents(const Request &request, const InputLayer &source, const InputLayer &target,
                              const Report &report) {
  OutputLayers out;
  out.mapped = source.has;  // the forward method: the source's own texture coordinates and colours
  out.mapped.vertexQuality = true;
  out.cut = out.mapped;
  if (report.texCoordsPulled) {  // per wedge, in the target's textures
    out.cut.wedgeTexCoords = true;
    out.cut.vertexTexCoords = false;
    out.cutHasTargetTextures = true;
  }
  out.cut.vertexColours = source.has.vertexColours || (request.options.transferColour && target.has.vertexColours);
  return out;
}

QString LayerLine(const QString &label, const Mesh &mesh) {
  return QString("new layer %1: %2 vertices, %3 faces").arg(label).arg(mesh.VN()).arg(mesh.FN());
}

std::map<std::string, QVariant> ReportFigures(const Report &report) {
  std::map<std::string, QVariant> figures;
  for (const Figure &f : FigureTable())
    figures[f.name] = f.unit == FigureUnit::Count ? QVariant(int(f.value(report))) : QVariant(f.value(report));
  return figures;
}

}  // namespace eulermap::plugin
