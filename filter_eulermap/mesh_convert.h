// Copies between a MeshLab layer's mesh (CMeshO, single precision, optional components)
// and the core's eulermap::Mesh (double precision, every component present).
//
// One copy, templated on both mesh types, serves both directions and both flavours (each
// instantiates it with its own CMeshO). vcg::tri::Append cannot do it for MeshLab 2020.09:
// its per-wedge texture-coordinate import assigns TexCoord2<float> from TexCoord2<double>
// (no conversion exists), so the copy is spelled out with vcglib's Import() per component.
#pragma once

#include "core/mesh.h"

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/topology.h>

#include <vector>

namespace eulermap::plugin {

// What a layer carries besides positions and faces (MeshLab's data mask).
struct LayerComponents {
  bool vertexTexCoords = false;
  bool wedgeTexCoords = false;
  bool vertexColours = false;
  bool vertexQuality = false;
};

// in:  `from` (deleted elements skipped), and which optional components to carry over
// out: `to`, replaced: positions, colours, per-vertex quality, per-vertex and per-wedge texture
//      coordinates when `has` says so, texture names; vertex i of `to` is the i-th
//      non-deleted vertex of `from`. Bounding box and normals updated. Either mesh may be
//      the layer's or the core's: one copy for both directions.
template <class From, class To>
void CopyMesh(const From &from, const LayerComponents &has, To &to) {
  to.Clear();
  std::vector<int> index(from.vert.size(), -1);
  vcg::tri::Allocator<To>::AddVertices(to, size_t(from.VN()));
  int n = 0;
  for (size_t i = 0; i < from.vert.size(); ++i) {
    const auto &v = from.vert[i];
    if (v.IsD()) continue;
    auto &w = to.vert[n];
    w.P().Import(v.cP());
    w.C() = v.cC();
    if (has.vertexQuality) w.Q() = typename To::VertexType::QualityType(v.cQ());
    if (has.vertexTexCoords) w.T().Import(v.cT());
    index[i] = n++;
  }
  vcg::tri::Allocator<To>::AddFaces(to, size_t(from.FN()));
  int f = 0;
  for (const auto &face : from.face) {
    if (face.IsD()) continue;
    auto &g = to.face[f++];
    for (int k = 0; k < 3; ++k) {
      g.V(k) = &to.vert[index[vcg::tri::Index(from, face.cV(k))]];
      if (has.wedgeTexCoords) g.WT(k).Import(face.cWT(k));
    }
  }
  to.textures = from.textures;
  vcg::tri::UpdateBounding<To>::Box(to);
  vcg::tri::UpdateNormal<To>::PerVertexNormalizedPerFaceNormalized(to);
}

// The layer as the core's input: CopyMesh, and face-face / vertex-face adjacency (the core
// copies meshes with their adjacency).
template <class LayerMesh>
void LayerToCore(const LayerMesh &layer, const LayerComponents &has, Mesh &core) {
  CopyMesh(layer, has, core);
  vcg::tri::UpdateTopology<Mesh>::FaceFace(core);
  vcg::tri::UpdateTopology<Mesh>::VertexFace(core);
}

}  // namespace eulermap::plugin
