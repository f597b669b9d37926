#include "refine_stretched.h"

#include "edge_faces.h"
#include "quality.h"
#include "surgery.h"
#include "topology.h"

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/refine.h>
#include <vcg/complex/algorithms/update/topology.h>

#include <array>
#include <utility>
#include <vector>

namespace eulermap {

namespace {

using Handle = Mesh::PerVertexAttributeHandle<Point3>;
using Pos = vcg::face::Pos<Face>;

// Normals whose cosine is below this face opposite ways (a corner of a box is 0, the two
// sides of a thin part -1).
constexpr double kOppositeCosine = -0.5;

// Where the ends face opposite ways, a chord round a thin part's rim has its midpoint nearer
// the target than this share of its length; one straight through the part has it half its
// length inside. (Splitting those too: chair -> stool at 64 cells 0.90% -> 1.25% flipped.)
constexpr double kRimSag = 0.25;

// AcrossGap, with the target's points nearest the chord's ends and midpoint already found.
bool GapAt(const Point3 &a, const Point3 &b, const ClosestHit &atA, const ClosestHit &atMid, const ClosestHit &atB) {
  if (!atMid.face || ((a + b) / 2 - atMid.point) * atMid.face->cN() <= 0) return false;  // the midpoint inside
  const double length = vcg::Distance(a, b);
  if (atMid.distance > kGapSag * length) return true;
  if (!atA.face || !atB.face) return false;
  const Point3 &na = atA.face->cN(), &nb = atB.face->cN();
  return atMid.distance > kLipSag * length && na * nb < kOppositeCosine && (b - a) * na > 0 && (a - b) * nb > 0;
}

// Whether the chord between images a and b follows the target (see the header): it crosses
// no gap, the target at the midpoint's nearest point does not face opposite to it at either
// end, and where the ends face opposite ways the chord runs round a thin part's rim
// (kRimSag). Where it does, atA and atB are the target's points nearest to a and b.
bool FollowsTarget(const Point3 &a, const Point3 &b, const ClosestPoint &target, ClosestHit &atA, ClosestHit &atB) {
  atA = target.Query(a), atB = target.Query(b);
  const ClosestHit atMid = target.Query((a + b) / 2);
  if (!atA.face || !atB.face || !atMid.face || GapAt(a, b, atA, atMid, atB)) return false;
  const Point3 &na = atA.face->cN(), &nb = atB.face->cN(), &nm = atMid.face->cN();
  return nm * na > kOppositeCosine && nm * nb > kOppositeCosine &&
         (na * nb > kOppositeCosine || atMid.distance < kRimSag * vcg::Distance(a, b));
}

// RefineE's predicate: pick(a, b) on the images of the edge's ends, for edges whose ends
// both lie off the faces set aside (see RefineChosen).
template <class Pick> struct Picked {
  Mesh &mesh;
  Handle &image;  // vcglib's handles read through a non-const operator[]
  const std::vector<char> &asideVertex;  // per vertex of the mesh before the passes
  const Pick &pick;
  bool Aside(const Vertex *v) const {
    const std::size_t n = vcg::tri::Index(mesh, v);
    return n < asideVertex.size() && asideVertex[n];
  }
  bool operator()(const Pos &ep) const {
    return !Aside(ep.V()) && !Aside(ep.VFlip()) && pick(image[ep.V()], image[ep.VFlip()]);
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

// Splits at their midpoints, pass after pass, the edges pick(a, b) chooses (a, b: the images
// of their ends), until none is chosen, `passes` have run or cut has doubled its vertices.
// Returns the number of vertices added.
template <class Pick> int RefineChosen(Mesh &cut, const ClosestPoint &target, int passes, const Pick &pick) {
  // RefineE walks manifold edges: the faces around an edge of more than two are set aside
  // (deleted while it runs), and no edge with an end on them is split, so they stay whole.
  // (vcglib 2020.09's CountNonManifoldEdgeFF takes a face bit flag it never gives back:
  // called once per map it runs out of bits.)
  const EdgeFaces edges(cut);
  std::vector<std::pair<std::size_t, std::array<std::size_t, 3>>> aside;  // face, its vertices
  std::vector<char> asideVertex(cut.vert.size(), 0);
  for (const Face &f : cut.face) {
    if (f.IsD()) continue;
    bool nonManifold = false;
    for (int e = 0; e < 3; ++e)
      nonManifold = nonManifold ||
                    edges.Around(int(vcg::tri::Index(cut, f.cV(e))), int(vcg::tri::Index(cut, f.cV((e + 1) % 3)))).size() > 2;
    if (!nonManifold) continue;
    std::array<std::size_t, 3> v;
    for (int c = 0; c < 3; ++c) asideVertex[v[c] = vcg::tri::Index(cut, f.cV(c))] = 1;
    aside.push_back({vcg::tri::Index(cut, f), v});
  }
  for (const auto &[f, v] : aside) vcg::tri::Allocator<Mesh>::DeleteFace(cut, cut.face[f]);
  vcg::tri::UpdateTopology<Mesh>::FaceFace(cut);
  Handle image = vcg::tri::Allocator<Mesh>::GetPerVertexAttribute<Point3>(cut, "TargetPosition");
  const int before = cut.vn;
  for (int pass = 0; pass < passes && cut.vn < 2 * before; ++pass) {
    Picked<Pick> picked{cut, image, asideVertex, pick};
    SplitPoint split{cut, image, target};
    if (!vcg::tri::RefineE(cut, split, picked)) break;  // (RefineE updates FF adjacency)
  }
  // Back with their corners (vcglib moves no pointer of a deleted face when its vectors grow).
  for (const auto &[f, v] : aside) {
    Face &face = cut.face[f];
    for (int c = 0; c < 3; ++c) face.V(c) = &cut.vert[v[c]];
    face.ClearD();
    ++cut.fn;
  }
  if (!aside.empty()) vcg::tri::UpdateTopology<Mesh>::FaceFace(cut);
  return cut.vn - before;
}

} // namespace

int RefineStretched(Mesh &cut, const ClosestPoint &target, double limit) {
  // Each pass halves the stretched edges; the budget stops a tear that the guard lets by.
  return RefineChosen(cut, target, 8, [&](const Point3 &a, const Point3 &b) {
    ClosestHit atA, atB;
    return vcg::Distance(a, b) > limit && FollowsTarget(a, b, target, atA, atB);
  });
}

int RefineAtSeams(Mesh &cut, const Mesh &target, const ClosestPoint &index, const std::vector<int> &chart) {
  const Face *first = &target.face[0];
  const double limit = kSeamEdgeShare * MeanEdgeLength(target);
  return RefineChosen(cut, index, kSeamPasses, [&](const Point3 &a, const Point3 &b) {
    ClosestHit atA, atB;
    return vcg::Distance(a, b) > limit && FollowsTarget(a, b, index, atA, atB) &&
           chart[atA.face - first] != chart[atB.face - first];
  });
}

bool AcrossGap(const Point3 &a, const Point3 &b, const ClosestPoint &target) {
  return GapAt(a, b, target.Query(a), target.Query((a + b) / 2), target.Query(b));
}

namespace {

// The connected pieces of cut's faces (through shared edges, its face-face adjacency up to
// date): per face its piece (-1 where deleted), per piece its area on the source.
struct FacePieces {
  std::vector<int> of;
  std::vector<double> area;

  explicit FacePieces(const Mesh &cut) : of(cut.face.size(), -1) {
    std::vector<int> stack;
    for (std::size_t seed = 0; seed < cut.face.size(); ++seed) {
      if (cut.face[seed].IsD() || of[seed] >= 0) continue;
      of[seed] = int(area.size());
      area.push_back(0);
      stack.push_back(int(seed));
      while (!stack.empty()) {
        const Face &f = cut.face[stack.back()];
        stack.pop_back();
        area.back() += vcg::DoubleArea(f) / 2;
        for (int e = 0; e < 3; ++e) {
          const int g = int(vcg::tri::Index(cut, f.cFFp(e)));
          if (!cut.face[g].IsD() && of[g] < 0) of[g] = of[seed], stack.push_back(g);
        }
      }
    }
  }
};

} // namespace

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
  auto same = [&](const Topology &t) {
    return t.components == before.components && t.boundaryLoops == before.boundaryLoops &&
           t.eulerCharacteristic == before.eulerCharacteristic;
  };
  const FacePieces whole(cut);
  for (std::vector<int> piece : pieces) {
    std::vector<int> beside;  // the faces next to the piece (face-face adjacency as before it goes)
    for (int n : piece)
      for (int e = 0; e < 3; ++e) beside.push_back(int(vcg::tri::Index(cut, cut.face[n].FFp(e))));
    for (int n : piece) vcg::tri::Allocator<Mesh>::DeleteFace(cut, cut.face[n]);
    Topology after = MeasureTopology(cut);
    if (!same(after)) {
      // The islands it cuts off go with it.
      const FacePieces left(cut);
      const double island = kIslandShare * whole.area[whole.of[piece.front()]];
      std::vector<char> flap(left.area.size(), 0);
      for (int n : beside)
        if (!cut.face[n].IsD() && left.area[left.of[n]] < island) flap[left.of[n]] = 1;
      const std::size_t alone = piece.size();
      for (std::size_t n = 0; n < cut.face.size(); ++n)
        if (!cut.face[n].IsD() && flap[left.of[n]]) piece.push_back(int(n)), vcg::tri::Allocator<Mesh>::DeleteFace(cut, cut.face[n]);
      if (piece.size() > alone) after = MeasureTopology(cut);
    }
    if (same(after)) {
      removed += int(piece.size());
      continue;
    }
    for (int n : piece) cut.face[n].ClearD(), ++cut.fn;  // undone: the piece would change the cut
    vcg::tri::UpdateTopology<Mesh>::FaceFace(cut);         // adjacency with its faces back, for the next piece's
  }
  if (removed > 0) {
    vcg::tri::Clean<Mesh>::RemoveUnreferencedVertex(cut);
    vcg::tri::Allocator<Mesh>::CompactEveryVector(cut);
  }
  return removed;
}

} // namespace eulermap
