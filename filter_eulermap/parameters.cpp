#include "parameters.h"

namespace eulermap::plugin {

const std::vector<ParameterSpec> &Parameters() {
  using K = ParameterKind;
  const Options defaults;
  static const std::vector<ParameterSpec> specs = {
      {param::kSourceMesh, K::Mesh, {}, "Source mesh",
       "The surface M0 to map from (default: the current layer). It is left untouched; the results "
       "are new layers named after it (sphere.ply gives sphere_cut, sphere_mapped and, with "
       "fill_holes, sphere_filled).",
       {}},
      {param::kTargetMesh, K::Mesh, {}, "Target mesh",
       "The surface M1 to map onto. It may have a different genus or number of components than the "
       "source; it must be another layer than the source. It is left untouched.",
       {}},
      {param::kGridResolution, K::Int, defaults.gridResolution, "Grid resolution",
       "Cells on the longest side of the padded box holding both surfaces. The signed distance "
       "fields, the morph and the velocity fields live on this grid: finer grids follow thin "
       "parts and small handles better, at a cubic cost in memory and time. Features thinner "
       "than about two cells are lost. A grid too large for memory is refused with a message.",
       {}},
      {param::kSteps, K::Int, defaults.steps, "Time steps",
       "Number of steps from t = 0 (source) to t = 1 (target). Each step solves one velocity "
       "field (paper, Eqs. 2-6) and moves every tracked point along it (Eq. 7). More steps: "
       "smaller moves per step and fewer points lost on fast-changing parts.",
       {}},
      {param::kAlpha, K::Float, defaults.alpha, "Smoothness (alpha)",
       "Weight of the smoothness term alpha |grad V|^2 of the velocity energy (paper, Eq. 2). "
       "Larger values give smoother, less distorted maps but let points drift further from the "
       "moving surface, which the pull-back then corrects.",
       {}},
      {param::kHoleRadius, K::Float, defaults.holeRadius, "Hole radius (cells)",
       "Radius, in grid cells, of the sphere around a topology change of the moving surface inside "
       "which source faces are cut away (paper, Sec. 3). Larger radii "
       "cut bigger, cleaner holes.",
       {}},
      {param::kAlign, K::Enum, defaults.align == Align::None ? 0 : 1, "Alignment",
       "How the target is placed in the source's frame when no anchors are given: 'none' keeps "
       "it where it is; 'centre-and-scale' moves its centroid onto the source's and scales its "
       "bounding-box diagonal to the source's. With anchors, the similarity fitted to them is "
       "used instead. The map always lands on the target where it really is.",
       {"none", "centre-and-scale"}},
      {param::kSourceAnchors, K::OpenFile, QString(), "Source anchors (.pp)",
       "MeshLab picked-points file (Edit > PickPoints, saved as .pp) with named anchor points on "
       "the source. Empty: the .pp beside the source's file with the same base name "
       "(spot.obj -> spot.pp or spot_picked_points.pp), when there is one. Points are matched "
       "to the target's by name; a name on one side only, or a point farther than 2% of the "
       "bounding-box diagonal from its surface, is an error. 1-3 anchors fit a similarity; 4 or "
       "more non-coplanar anchors also steer the morph (ARAP + thin-plate warp).",
       {"*.pp"}},
      {param::kTargetAnchors, K::OpenFile, QString(), "Target anchors (.pp)",
       "MeshLab picked-points file with the target's anchor points, named as in the source's. "
       "Empty: the .pp beside the target's file, when there is one.",
       {"*.pp"}},
      {param::kAnchorPairs, K::String, QString(), "Anchor vertex pairs",
       "Anchors as pairs of vertex indices, source:target, separated by commas, e.g. "
       "'12:305, 40:77'. Used instead of .pp files when not empty (give one or the other).",
       {}},
      {param::kFillHoles, K::Bool, defaults.fillHoles, "Fill holes",
       "Also make the _filled layer: the cut source with the holes left by surgery closed again.",
       {}},
      {param::kTransferTexture, K::Bool, defaults.transferTexture, "Transfer texture",
       "When the target has texture coordinates (per wedge or per vertex), pull them back onto "
       "the _cut layer, per wedge, read at each vertex's image on the target, together with the "
       "target's texture file names, so the source shows the target's texture (paper, Sec. 4.1). "
       "A face never mixes two charts of the target's texture. The _mapped layer always keeps "
       "the source's own texture coordinates and texture: the source's texture on the target's "
       "shape.",
       {}},
      {param::kTransferColorQuality, K::Bool, false, "Transfer colour and quality",
       "Also pull the target's per-vertex colour and quality, those it has, onto the _cut layer "
       "through the map (interpolated at each vertex's image). The _cut layer's vertex quality "
       "then is the target's instead of the local distortion.",
       {}},
  };
  return specs;
}

QString FilterName() { return "Eulerian Surface Map"; }

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

Request ReadRequest(const std::function<QVariant(const ParameterSpec &)> &value) {
  Request r;
  for (const ParameterSpec &p : Parameters()) {
    const QVariant v = value(p);
    if (p.name == param::kSourceMesh) r.sourceLayer = v.toInt();
    else if (p.name == param::kTargetMesh) r.targetLayer = v.toInt();
    else if (p.name == param::kGridResolution) r.options.gridResolution = v.toInt();
    else if (p.name == param::kSteps) r.options.steps = v.toInt();
    else if (p.name == param::kAlpha) r.options.alpha = v.toDouble();
    else if (p.name == param::kHoleRadius) r.options.holeRadius = v.toDouble();
    else if (p.name == param::kAlign) r.options.align = v.toInt() == 0 ? Align::None : Align::CentreAndScale;
    else if (p.name == param::kSourceAnchors) r.sourceAnchors = v.toString().trimmed();
    else if (p.name == param::kTargetAnchors) r.targetAnchors = v.toString().trimmed();
    else if (p.name == param::kAnchorPairs) r.anchorPairs = v.toString().trimmed();
    else if (p.name == param::kFillHoles) r.options.fillHoles = v.toBool();
    else if (p.name == param::kTransferTexture) r.options.transferTexture = v.toBool();
    else if (p.name == param::kTransferColorQuality) r.transferColorQuality = v.toBool();
  }
  return r;
}

}  // namespace eulermap::plugin
