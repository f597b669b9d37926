#include "refine_stretched.h"

#include "edge_faces.h"
#include "topology.h"

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/refine.h>
#include <vcg/complex/algorithms/update/topology.h>

namespace eulermap {

namespace {

using Handle = Mesh::PerVertexAttributeHandle<Point3>;
using Pos = vcg::face::Pos<Face>;

// Normals whose cosine is below this face opposite ways (a corner of a box is 0, the two
// sides of a thin part -1).
constexpr double kOppositeCosine = -0.5;

// AcrossGap, with the target's point nearest the chord's midpoint already found.
bool GapAt(const Point3 &a, const Point3 &b, const ClosestHit &atMid) {
  return atMid.face && atMid.distance > kGapSag * vcg::Distance(a, b) &&
         ((a + b) / 2 - atMid.point) * atMid.face->cN() > 0;
}

// Which edges are split: mapped longer than the limit, along the target (see the header).
struct Stretched {
  Handle &image;  // vcglib's handles read through a non-const operator[]
  const ClosestPoint &target;
  double limit;
  bool operator()(const Pos &ep) const {
    const Point3 &a = image[ep.V()], &b = image[ep.VFlip()];
    const double length = vcg::Distance(a, b);
    if (length <= limit) return false;
    const ClosestHit atA = target.Query(a), atB = target.Query(b), atMid = target.Query((a + b) / 2);
    if (!atA.face || !atB.face || !atMid.face || GapAt(a, b, atMid)) return false;
    const Point3 &na = atA.face->cN(), &nb = atB.face->cN(), &nm = atMid.face->cN();
    return na * nb > kOppositeCosine && nm * na > kOppositeCosine && nm * nb > kOppositeCosine;
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

bool AcrossGap(const Point3 &a, const Point3 &b, const ClosestPoint &target) {
  return GapAt(a, b, target.Query((a + b) / 2));
}

int OpenTears(Mesh &cut, const ClosestPoint &target, double limit) {
  Handle image = vcg::tri::Allocator<Mesh>::GetPerVertexAttribute<Point3>(cut, "TargetPosition");
  std::vector<char> torn(cut.face.size(), 0);
  for (std::size_t n = 0; n < cut.face.size(); ++n)
    for (int e = 0; e < 3 && !torn[n]; ++e) {
      const Point3 &a = image[cut.face[n].cV(e)], &b = image[cut.face[n].cV((e + 1) % 3)];
      const double length = vcg::Distance(a, b);
      torn[n] = length > limit && AcrossGap(a, b, target);
    }
  const Topology before = MeasureTopology(cut);  // (updates face-face adjacency)
  // The connected pieces of torn faces that reach a rim.
  std::vector<std::vector<int>> pieces;
  std::vector<char> seen(cut.face.size(), 0);
  for (std::size_t seed = 0; seed < cut.face.size(); ++seed) {
    if (!torn[seed] || seen[seed]) continue;
    std::vector<int> piece, stack = {int(seed)};
    seen[seed] = 1;
    bool rim = false;
    while (!stack.empty()) {
      Face &f = cut.face[stack.back()];
      piece.push_back(stack.back());
      stack.pop_back();
      for (int e = 0; e < 3; ++e) {
        const int g = int(vcg::tri::Index(cut, f.FFp(e)));
        if (f.FFp(e) == &f) rim = true;
        else if (torn[g] && !seen[g]) seen[g] = 1, stack.push_back(g);
      }
    }
    if (rim) pieces.push_back(std::move(piece));
  }
  int removed = 0;
  for (const std::vector<int> &piece : pieces) {
    for (int n : piece) vcg::tri::Allocator<Mesh>::DeleteFace(cut, cut.face[n]);
    const Topology after = MeasureTopology(cut);
    if (after.components == before.components && after.boundaryLoops == before.boundaryLoops &&
        after.eulerCharacteristic == before.eulerCharacteristic) {
      removed += int(piece.size());
      continue;
    }
    for (int n : piece) cut.face[n].ClearD(), ++cut.fn;  // undone: the piece would change the cut
  }
  if (removed > 0) {
    vcg::tri::Clean<Mesh>::RemoveUnreferencedVertex(cut);
    vcg::tri::Allocator<Mesh>::CompactEveryVector(cut);
  }
  return removed;
}

} // namespace eulermap
