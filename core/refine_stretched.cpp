#include "refine_stretched.h"

#include "edge_faces.h"

#include <vcg/complex/algorithms/refine.h>
#include <vcg/complex/algorithms/update/topology.h>

namespace eulermap {

namespace {

using Handle = Mesh::PerVertexAttributeHandle<Point3>;
using Pos = vcg::face::Pos<Face>;

// Which edges are split: mapped longer than the limit, along the target (see the header).
struct Stretched {
  Handle &image;  // vcglib's handles read through a non-const operator[]
  const ClosestPoint &target;
  double limit;
  bool operator()(const Pos &ep) const {
    const Point3 &a = image[ep.V()], &b = image[ep.VFlip()];
    const double length = vcg::Distance(a, b);
    if (length <= limit) return false;
    const Point3 mid = (a + b) / 2;
    const ClosestHit atA = target.Query(a), atB = target.Query(b), atMid = target.Query(mid);
    if (!atA.face || !atB.face || !atMid.face) return false;
    const Point3 &na = atA.face->cN(), &nb = atB.face->cN(), &nm = atMid.face->cN();
    return atMid.distance <= kChordSag * length && na * nb > 0 && nm * na > 0 && nm * nb > 0;
  }
};

// The new vertex: the source's midpoint and data (vcglib's MidPoint), its image the
// target's point nearest the midpoint of the ends' images.
struct SplitPoint {
  Mesh &mesh;
  Handle &image;
  const ClosestPoint &target;
  vcg::tri::MidPoint<Mesh> source{&mesh};
  void operator()(Vertex &nv, Pos ep) {
    source(nv, ep);
    image[nv] = target.Query((image[ep.V()] + image[ep.VFlip()]) / 2).point;
  }
  template <class T> T WedgeInterp(T &a, T &b) { return source.WedgeInterp(a, b); }
};

} // namespace

int RefineStretched(Mesh &cut, const ClosestPoint &target, double limit) {
  // RefineE walks manifold edges. (vcglib 2020.09's CountNonManifoldEdgeFF takes a face
  // bit flag it never gives back: called once per map it runs out of bits.)
  const EdgeFaces edges(cut);
  for (const Face &f : cut.face)
    for (int e = 0; e < 3; ++e)
      if (edges.Around(int(vcg::tri::Index(cut, f.cV(e))), int(vcg::tri::Index(cut, f.cV((e + 1) % 3)))).size() > 2)
        return 0;
  vcg::tri::UpdateTopology<Mesh>::FaceFace(cut);
  Handle image = vcg::tri::Allocator<Mesh>::GetPerVertexAttribute<Point3>(cut, "TargetPosition");
  const int before = cut.vn;
  // Each pass halves the stretched edges; the budget stops a tear that the guard lets by.
  for (int pass = 0; pass < 8 && cut.vn < 2 * before; ++pass) {
    Stretched stretched{image, target, limit};
    SplitPoint split{cut, image, target};
    if (!vcg::tri::RefineE(cut, split, stretched)) break;  // (RefineE updates FF adjacency)
  }
  return cut.vn - before;
}

} // namespace eulermap
