// Copies between a MeshLab layer's mesh (CMeshO, single precision, optional components)
// and the core's eulermap::Mesh (double precision, every component present).
//
// Templates on the MeshLab mesh type, so each flavour instantiates them with its own
// CMeshO. vcg::tri::Append cannot do this copy: its per-wedge texture-coordinate import
// assigns TexCoord2<float> from TexCoord2<double> (no conversion exists), so the copy is
// spelled out here with vcglib's Import() for each component.
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

// in:  `layer` (deleted elements are skipped), and which optional components it has
//      enabled (MeshLab's data mask)
// out: `core`: positions, normals, colours, per-vertex and per-wedge texture coordinates
//      when present, vertex quality, texture names; bounding box, normals and face-face / vertex-face
//      adjacency updated (the core copies meshes with their adjacency). Vertex i of
//      `core` is the i-th non-deleted vertex of `layer`.
template <class LayerMesh>
void LayerToCore(const LayerMesh &layer, const LayerComponents &has, Mesh &core) {
  core.Clear();
  std::vector<int> index(layer.vert.size(), -1);
  vcg::tri::Allocator<Mesh>::AddVertices(core, size_t(layer.VN()));
  int n = 0;
  for (size_t i = 0; i < layer.vert.size(); ++i) {
    const auto &v = layer.vert[i];
    if (v.IsD()) continue;
    auto &w = core.vert[n];
    w.P().Import(v.cP());
    w.N().Import(v.cN());
    w.C() = v.cC();
    if (has.vertexQuality) w.Q() = v.cQ();
    if (has.vertexTexCoords) w.T().Import(v.cT());
    index[i] = n++;
  }
  vcg::tri::Allocator<Mesh>::AddFaces(core, size_t(layer.FN()));
  int f = 0;
  for (const auto &face : layer.face) {
    if (face.IsD()) continue;
    auto &g = core.face[f++];
    for (int k = 0; k < 3; ++k) {
      g.V(k) = &core.vert[index[vcg::tri::Index(layer, face.cV(k))]];
      if (has.wedgeTexCoords) g.WT(k).Import(face.cWT(k));
    }
  }
  core.textures = layer.textures;
  vcg::tri::UpdateBounding<Mesh>::Box(core);
  vcg::tri::UpdateNormal<Mesh>::PerVertexNormalizedPerFaceNormalized(core);
  vcg::tri::UpdateTopology<Mesh>::FaceFace(core);
  vcg::tri::UpdateTopology<Mesh>::VertexFace(core);
}

// in:  `core` (deleted elements skipped), and which texture coordinates to carry over
// out: `layer`, replaced: positions, per-vertex quality, wedge (and vertex) texture
//      coordinates when asked, texture names; the caller enables the matching optional
//      components on the layer (MeshLab's updateDataMask) before calling. Vertex i of
//      `layer` is the i-th non-deleted vertex of `core`. Bounding box and normals updated.
template <class LayerMesh>
void CoreToLayer(const Mesh &core, const LayerComponents &has, LayerMesh &layer) {
  layer.Clear();
  std::vector<int> index(core.vert.size(), -1);
  vcg::tri::Allocator<LayerMesh>::AddVertices(layer, size_t(core.VN()));
  int n = 0;
  for (size_t i = 0; i < core.vert.size(); ++i) {
    const Vertex &v = core.vert[i];
    if (v.IsD()) continue;
    auto &w = layer.vert[n];
    w.P().Import(v.cP());
    w.Q() = typename LayerMesh::VertexType::QualityType(v.cQ());
    w.C() = v.cC();
    if (has.vertexTexCoords) w.T().Import(v.cT());
    index[i] = n++;
  }
  vcg::tri::Allocator<LayerMesh>::AddFaces(layer, size_t(core.FN()));
  int f = 0;
  for (const Face &face : core.face) {
    if (face.IsD()) continue;
    auto &g = layer.face[f++];
    for (int k = 0; k < 3; ++k) {
      g.V(k) = &layer.vert[index[vcg::tri::Index(core, face.cV(k))]];
      if (has.wedgeTexCoords) g.WT(k).Import(face.cWT(k));
    }
  }
  layer.textures = core.textures;
  vcg::tri::UpdateBounding<LayerMesh>::Box(layer);
  vcg::tri::UpdateNormal<LayerMesh>::PerVertexNormalizedPerFaceNormalized(layer);
}

}  // namespace eulermap::plugin
