#include "transfer.h"

namespace eulermap {

TexCoordKind DetectTexCoords(const Mesh &m) {
  for (const Face &f : m.face)
    if (!f.IsD())
      for (int c = 0; c < 3; ++c)
        if (f.cWT(c).P() != vcg::Point2d(0, 0)) return TexCoordKind::PerWedge;
  for (const Vertex &v : m.vert)
    if (!v.IsD() && v.cT().P() != vcg::Point2d(0, 0)) return TexCoordKind::PerVertex;
  return TexCoordKind::None;
}

bool PullTexCoords(Mesh &cut, const Mesh &target, const std::vector<ClosestHit> &hits, const Mesh &hitMesh) {
  const TexCoordKind kind = DetectTexCoords(target);
  if (kind == TexCoordKind::None) return false;
  for (Face &f : cut.face) {
    if (f.IsD()) continue;
    for (int c = 0; c < 3; ++c) {
      const ClosestHit &hit = hits[vcg::tri::Index(cut, f.V(c))];
      const Face &tf = target.face[hit.face - &hitMesh.face[0]];
      vcg::Point2d uv(0, 0);
      for (int k = 0; k < 3; ++k)
        uv += (kind == TexCoordKind::PerWedge ? tf.cWT(k).P() : tf.cV(k)->cT().P()) * hit.barycentric[k];
      f.WT(c).P() = uv;
      f.WT(c).N() = kind == TexCoordKind::PerWedge ? tf.cWT(0).N() : 0;
    }
  }
  cut.textures = target.textures;
  return true;
}

} // namespace eulermap
