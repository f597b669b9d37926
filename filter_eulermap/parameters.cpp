#include "parameters.h"

namespace eulermap::plugin {

QStringList Choices(const Parameter &p) {
  QStringList choices;
  for (const std::string &c : p.choices) choices << QString::fromStdString(c);
  return choices;
}

QString FilterName() { return kFilterName; }

QString FilterDescription() {
  return "Builds a dense map from a source surface to a target surface of possibly different "
         "topology (genus, number of components). Both surfaces become signed distance fields "
         "on a common grid; the field is morphed from the source to the target (optionally "
         "steered by named anchor points), a smooth velocity field is solved at every time "
         "step, and every source vertex is advected along it and kept on the moving surface. "
         "Where the moving surface changes topology (found exactly from the field), the faces "
         "there are cut from the source.<br><br>"
         "New layers: <b>&lt;source&gt;_cut</b> (the source minus the removed discs, original "
         "positions, per-vertex attribute <i>TargetPosition</i>, vertex quality = local "
         "distortion, texture coordinates, colour and quality from the target when asked), "
         "<b>&lt;source&gt;_mapped</b> (same vertices and faces, at their images on the "
         "target, with the source's own texture) and, on request, <b>&lt;source&gt;_filled</b>. "
         "The input layers are not changed. The log reports the grid, the anchors, every topology event, the time per "
         "stage and the map's quality.<br><br>"
         "See: <br>"
         "<i>Hyeongjun Park, Youngjoong Cho, Seungbae Bang, Sung-Hee Lee</i><br>"
         "<b>\"An Eulerian approach for constructing a map between surfaces with different "
         "topologies\"</b><br>"
         "Computer Graphics Forum, 2016.";
}

Request ReadRequest(const std::function<QVariant(const Parameter &)> &value) {
  Request r;
  for (const Parameter &p : Parameters()) {
    if (!p.inFilter) continue;
    const QVariant v = value(p);
    const std::string name = p.name;
    if (p.set) p.set(r.options, v.toDouble());
    else if (name == parameter::kSourceMesh) r.sourceLayer = v.toInt();
    else if (name == parameter::kTargetMesh) r.targetLayer = v.toInt();
    else if (name == parameter::kSourceAnchors) r.sourceAnchors = v.toString().trimmed();
    else if (name == parameter::kTargetAnchors) r.targetAnchors = v.toString().trimmed();
    else if (name == parameter::kAnchorPairs) r.anchorPairs = v.toString().trimmed();
  }
  return r;
}

}  // namespace eulermap::plugin
