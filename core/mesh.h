// eulermap::Mesh — the core's triangle mesh, a vcglib TriMesh in double precision.
//
// The MeshLab adapter copies layers into and out of this type (filter_eulermap/
// mesh_convert.h, CopyMesh), so the core never sees CMeshO.
// Components: positions, normals, flags, quality (per-vertex distortion), colour,
// per-vertex and per-wedge texture coordinates (targets may carry either),
// FF/VF adjacency for topology and cleaning, and Mark for spatial queries.
#pragma once

#include <vcg/complex/complex.h>

namespace eulermap {

// Texture coordinates that start at (0,0), index 0. vcglib's TexCoord2 leaves them
// uninitialised, and a mesh read from a file without them would carry garbage that
// DetectTexCoords (transfer.h) takes for coordinates.
template <class T> class ZeroTexCoord2d : public vcg::vertex::TexCoord2d<T> {
 public:
  ZeroTexCoord2d() { this->T() = vcg::TexCoord2d(0, 0); }
};
template <class T> class ZeroWedgeTexCoord2d : public vcg::face::WedgeTexCoord2d<T> {
 public:
  ZeroWedgeTexCoord2d() {
    for (int c = 0; c < 3; ++c) this->WT(c) = vcg::TexCoord2d(0, 0);
  }
};

class Vertex;
class Face;
struct UsedTypes : public vcg::UsedTypes<vcg::Use<Vertex>::AsVertexType, vcg::Use<Face>::AsFaceType> {};

class Vertex : public vcg::Vertex<UsedTypes, vcg::vertex::Coord3d, vcg::vertex::Normal3d,
                                  vcg::vertex::BitFlags, vcg::vertex::Qualityd, vcg::vertex::Color4b,
                                  ZeroTexCoord2d, vcg::vertex::VFAdj, vcg::vertex::Mark> {};

class Face : public vcg::Face<UsedTypes, vcg::face::VertexRef, vcg::face::Normal3d, vcg::face::BitFlags,
                              ZeroWedgeTexCoord2d, vcg::face::FFAdj, vcg::face::VFAdj, vcg::face::Mark> {};

class Mesh : public vcg::tri::TriMesh<std::vector<Vertex>, std::vector<Face>> {
 public:
  // vcglib's ~TriMesh (2020.09 and 2025.07) leaves ClearAttributes() commented out, so
  // every attribute added with Allocator<Mesh>::Add/GetPer*Attribute (e.g. the cut's
  // TargetPosition) would leak. ClearAttributes deletes each one and empties the sets;
  // Clear() does not touch attributes and TriMesh cannot be copied, so none is freed twice.
  ~Mesh() { ClearAttributes(); }
};

using Point3 = vcg::Point3d;
using Box3 = vcg::Box3d;

} // namespace eulermap
