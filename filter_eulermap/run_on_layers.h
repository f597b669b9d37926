// The filter's run on a MeshLab document, the same for every flavour: the layer choice
// checked, the two layers copied into the core (mesh_convert.h), MapLayers, the new layers
// added (<source>_cut with the per-vertex attribute TargetPosition, <source>_mapped and, on
// request, <source>_filled), the log's lines and the progress bar.
//
// Templates on the flavour's MeshModel, whose API for this (label, fullName, hasDataMask,
// updateDataMask, cm) is the same in MeshLab 2020.09 and 2025.07. The shim includes its
// MeshLab headers first and says, in a LayerDocument, how its document numbers, finds and
// adds layers.
#pragma once

#include "map_layers.h"

#include <vcg/complex/allocate.h>

#include <functional>
#include <memory>
#include <vector>

namespace eulermap::plugin {

// A MeshLab document as the run sees it.
template <class Model>
struct LayerDocument {
  std::vector<int> layers;                      // the numbers users choose layers by (2020.09: the
                                                // position in the document; 2025.07: the layer id)
  std::function<Model *(int)> layer;            // the layer with that number
  std::function<Model *(const QString &)> add;  // a new, empty layer with that label; the current
                                                // layer stays as it is
  // Gives a new layer the texture images of a layer whose texture names it carries
  // (2025.07 layers hold their images; 2020.09's GUI loads them into its OpenGL context).
  std::function<void(Model &to, const Model &from)> copyTextureImages;
};

// in:  a layer
// out: `layer`: its label, file and texture-coordinate components, and its mesh in the core's type
template <class Model>
void ToInput(const Model &m, InputLayer &layer) {
  layer.label = m.label();
  layer.fileName = m.fullName();
  layer.has.vertexTexCoords = m.hasDataMask(Model::MM_VERTTEXCOORD);
  layer.has.wedgeTexCoords = m.hasDataMask(Model::MM_WEDGTEXCOORD);
  layer.has.vertexColours = m.hasDataMask(Model::MM_VERTCOLOR);
  layer.has.vertexQuality = m.hasDataMask(Model::MM_VERTQUALITY);
  LayerToCore(m.cm, layer.has, layer.mesh);
}

// in:  a new layer `m`, the mesh to put there, which texture coordinates it carries and,
//      for the cut layer, the images of its vertices
// out: `m` holds `mesh` with the components `has` names; with `targetPositions`, their
//      vertices (the i-th non-deleted one for the i-th vertex) become its per-vertex
//      attribute "TargetPosition"
template <class Model>
void FillLayer(Model &m, const Mesh &mesh, const LayerComponents &has, const Mesh *targetPositions) {
  using LayerMesh = decltype(m.cm);
  using Point = typename LayerMesh::CoordType;
  int mask = Model::MM_NONE;
  if (has.vertexQuality) mask |= Model::MM_VERTQUALITY;
  if (has.vertexColours) mask |= Model::MM_VERTCOLOR;
  if (has.wedgeTexCoords) mask |= Model::MM_WEDGTEXCOORD;
  if (has.vertexTexCoords) mask |= Model::MM_VERTTEXCOORD;
  m.updateDataMask(mask);
  CopyMesh(mesh, has, m.cm);
  if (!targetPositions) return;
  auto target = vcg::tri::Allocator<LayerMesh>::template GetPerVertexAttribute<Point>(m.cm, "TargetPosition");
  size_t i = 0;
  for (const Vertex &v : targetPositions->vert)
    if (!v.IsD() && i < m.cm.vert.size()) target[m.cm.vert[i++]].Import(v.cP());
}

// MeshLab's progress callback as a ProgressFn that passes a report on only when the
// percentage or the stage changed; null `cb`: no progress shown.
inline ProgressFn MeshLabProgress(vcg::CallBackPos *cb) {
  struct Last {
    int percent = -1;
    QString stage;
  };
  auto last = std::make_shared<Last>();
  return [cb, last](int percent, const QString &stage) {
    if (!cb || (percent == last->percent && stage == last->stage)) return true;
    last->percent = percent;
    last->stage = stage;
    return cb(percent, qUtf8Printable(stage));
  };
}

// in:  the request (ReadRequest), the document, progress, log (called once per line)
// out: true, `result` (its report as the log gave it) and the new layers in the document;
//      false and `error` (what to change) otherwise, the document unchanged. Never throws.
template <class Model>
bool RunOnLayers(const Request &request, const LayerDocument<Model> &doc, const ProgressFn &progress,
                 const std::function<void(const QString &)> &log, Result &result, QString &error) {
  if (!CheckLayerChoice(request, doc.layers, error)) return false;
  progress(0, "Eulerian map: copying layers");
  InputLayer source, target;
  ToInput(*doc.layer(request.sourceLayer), source);
  ToInput(*doc.layer(request.targetLayer), target);

  QStringList lines;
  const bool ok = MapLayers(request, source, target, progress, result, lines, error);
  for (const QString &line : lines) log(line);
  if (!ok) return false;

  progress(kProgressCoreEnd, "Eulerian map: making layers");
  const OutputLayers out = OutputComponents(request, source, target, result.report);
  const Model &cutTextures = *doc.layer(out.cutHasTargetTextures ? request.targetLayer : request.sourceLayer);
  const auto addLayer = [&](const char *suffix, const Mesh &mesh, const LayerComponents &has,
                            const Model &textures, const Mesh *targetPositions) {
    Model *m = doc.add(OutputLabel(source.label, suffix));
    FillLayer(*m, mesh, has, targetPositions);
    if (doc.copyTextureImages) doc.copyTextureImages(*m, textures);
    log(LayerLine(m->label(), mesh));
  };
  addLayer("cut", result.cut, out.cut, cutTextures, &result.mapped);
  addLayer("mapped", result.mapped, out.mapped, *doc.layer(request.sourceLayer), nullptr);
  if (request.options.fillHoles) {
    if (result.filled.FN() > 0)
      addLayer("filled", result.filled, out.cut, cutTextures, nullptr);
    else
      log("warning: fill_holes gave no faces, so no " + OutputLabel(source.label, "filled") + " layer was made");
  }
  progress(100, "Eulerian map: done");
  return true;
}

}  // namespace eulermap::plugin
