#include "input.h"

#include "edge_faces.h"
#include "union_find.h"

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/update/bounding.h>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace eulermap {

namespace {

bool Finite(const Point3 &p) { return std::isfinite(p.X()) && std::isfinite(p.Y()) && std::isfinite(p.Z()); }

void Note(std::vector<std::string> &notes, const std::string &role, int count, const std::string &what) {
  if (count > 0) notes.push_back(role + ": " + std::to_string(count) + " " + what);
}

// Removes the faces `remove` says, then the vertices left without a face; returns the number
// of vertices removed.
template <class Pred> int RemoveFacesWhere(Mesh &mesh, Pred remove, int &faces) {
  faces = 0;
  for (Face &f : mesh.face)
    if (!f.IsD() && remove(f)) vcg::tri::Allocator<Mesh>::DeleteFace(mesh, f), ++faces;
  return vcg::tri::Clean<Mesh>::RemoveUnreferencedVertex(mesh);
}

// Step 5 of PrepareMesh: vertices with the same position, texture coordinate and colour
// become one (the first in storage order); returns how many went.
int Weld(Mesh &mesh) {
  std::vector<Vertex *> order;
  for (Vertex &v : mesh.vert)
    if (!v.IsD()) order.push_back(&v);
  auto key = [](const Vertex *v) {
    return std::make_tuple(v->cP().X(), v->cP().Y(), v->cP().Z(), v->cT().U(), v->cT().V(), v->cC()[0], v->cC()[1],
                           v->cC()[2], v->cC()[3]);
  };
  std::stable_sort(order.begin(), order.end(), [&](const Vertex *a, const Vertex *b) { return key(a) < key(b); });
  std::vector<Vertex *> into(mesh.vert.size(), nullptr);  // per vertex index: the vertex it merges into
  int merged = 0;
  for (std::size_t n = 1; n < order.size(); ++n)
    if (key(order[n]) == key(order[n - 1])) {
      Vertex *first = into[vcg::tri::Index(mesh, order[n - 1])];
      into[vcg::tri::Index(mesh, order[n])] = first ? first : order[n - 1];
      ++merged;
    }
  if (merged == 0) return 0;
  for (Face &f : mesh.face)
    if (!f.IsD())
      for (int c = 0; c < 3; ++c)
        if (Vertex *to = into[vcg::tri::Index(mesh, f.V(c))]) f.V(c) = to;
  for (std::size_t n = 0; n < into.size(); ++n)
    if (into[n]) vcg::tri::Allocator<Mesh>::DeleteVertex(mesh, mesh.vert[n]);
  return merged;
}

// Connected parts of the live faces (faces sharing a vertex): per face index, its part.
std::vector<int> FaceParts(const Mesh &mesh, int &parts) {
  UnionFind vertices(int(mesh.vert.size()));
  for (const Face &f : mesh.face)
    if (!f.IsD())
      for (int c = 1; c < 3; ++c) vertices.Merge(int(vcg::tri::Index(mesh, f.cV(c))), int(vcg::tri::Index(mesh, f.cV(0))));
  std::vector<int> label(mesh.vert.size(), -1), part(mesh.face.size(), -1);
  parts = 0;
  for (std::size_t n = 0; n < mesh.face.size(); ++n) {
    if (mesh.face[n].IsD()) continue;
    const int root = vertices.Find(int(vcg::tri::Index(mesh, mesh.face[n].cV(0))));
    if (label[root] < 0) label[root] = parts++;
    part[n] = label[root];
  }
  return part;
}

// Step 6 of PrepareMesh, first half: within each part, faces turned to agree with the
// neighbour they were reached from across a manifold edge (an edge of exactly two faces),
// breadth first from the part's first face; returns the faces turned. Faces that disagree
// with their neighbours make the winding number cancel (every other face turned over reads
// as no inside at all).
int OrientCoherently(Mesh &mesh) {
  const EdgeFaces edgeFaces(mesh);
  auto index = [&](const Face &f, int c) { return int(vcg::tri::Index(mesh, f.cV(c))); };
  // Whether face g runs along a -> b, as the face it is reached from does (then they disagree).
  auto runsAlong = [&](const Face &g, int a, int b) {
    for (int e = 0; e < 3; ++e)
      if (index(g, e) == a && index(g, (e + 1) % 3) == b) return true;
    return false;
  };
  std::vector<char> seen(mesh.face.size(), 0);
  int turned = 0;
  for (std::size_t start = 0; start < mesh.face.size(); ++start) {
    if (mesh.face[start].IsD() || seen[start]) continue;
    std::vector<int> queue{int(start)};
    seen[start] = 1;
    for (std::size_t q = 0; q < queue.size(); ++q) {
      Face &f = mesh.face[queue[q]];
      for (int e = 0; e < 3; ++e) {
        const int a = index(f, e), b = index(f, (e + 1) % 3);
        const EdgeFaces::Faces faces = edgeFaces.Around(a, b);
        if (faces.size() != 2) continue;
        const int g = faces[0] == queue[q] ? faces[1] : faces[0];
        if (seen[g]) continue;
        seen[g] = 1;
        if (runsAlong(mesh.face[g], a, b)) {
          std::swap(mesh.face[g].V(1), mesh.face[g].V(2));
          std::swap(mesh.face[g].WT(1), mesh.face[g].WT(2));
          ++turned;
        }
        queue.push_back(g);
      }
    }
  }
  return turned;
}

// Step 6 of PrepareMesh, second half: parts whose signed volume (1/6 sum of p0 . (p1 x p2), about the
// part's centroid) is negative have every face turned; returns the faces turned.
int OrientOutward(Mesh &mesh) {
  int parts = 0;
  const std::vector<int> part = FaceParts(mesh, parts);
  std::vector<Point3> centre(parts, Point3(0, 0, 0));
  std::vector<double> count(parts, 0), volume(parts, 0);
  for (std::size_t n = 0; n < mesh.face.size(); ++n)
    if (part[n] >= 0)
      for (int c = 0; c < 3; ++c) centre[part[n]] += mesh.face[n].cP(c), count[part[n]] += 1;
  for (int p = 0; p < parts; ++p) centre[p] /= count[p];
  for (std::size_t n = 0; n < mesh.face.size(); ++n)
    if (part[n] >= 0) {
      const Face &f = mesh.face[n];
      const Point3 &o = centre[part[n]];
      volume[part[n]] += (f.cP(0) - o).dot((f.cP(1) - o) ^ (f.cP(2) - o));
    }
  int turned = 0;
  for (std::size_t n = 0; n < mesh.face.size(); ++n)
    if (part[n] >= 0 && volume[part[n]] < 0) {
      Face &f = mesh.face[n];
      std::swap(f.V(1), f.V(2));
      std::swap(f.WT(1), f.WT(2));
      ++turned;
    }
  return turned;
}

// A face's height over its longest edge, 2 area / longest edge, below kFlatHeight of the
// diagonal: below what single-precision coordinates resolve (MeshLab 2020.09 and STL files
// store floats; a face on three collinear points rounded to floats has a height of 1e-9
// to 1e-8 of the diagonal, a sound face of a 10^6-face scan one of 1e-4 or so).
constexpr double kFlatHeight = 1e-6;
// A flat face whose shortest edge is below kNeedle of its longest is a needle: two corners
// at nearly one place, the third far off. Flipping its longest edge only hands the short edge
// to the next face (stool3 of tests/support/shapes.h at 128 cells: two needles 1.4e-6 long,
// just over the flatness bound, flipped for 8 rounds, then removed: 2 holes); welding the two
// corners moves one by under a thousandth of the face.
constexpr double kNeedle = 1e-3;

struct FlatFaces {
  int welded = 0, flipped = 0, removed = 0, orphans = 0;  // faces mended each way; removed, and vertices only they used
};

// Step 5 of PrepareMesh: faces whose height is at most `flat` mended where the surface closes
// round them (each of their edges has exactly one other face), so that it stays closed:
// corners nearer each other than `flat`, or than kNeedle of the longest edge, are welded (the
// edge collapses; the face and its neighbour across that edge go), else a corner lies on the
// opposite, longest edge, which is
// flipped (the face and its neighbour across it become the two faces on the quad's other
// diagonal). Removing such a face would open a hole that changes the surface's topology, and
// so the cut a continuous map needs: marching cubes makes them where the surface passes
// through a grid node (the spectacles of tests/support/shapes.h at every grid; 4 faces of a
// trefoil knot's tube at 64 cells, 28 of two merged balls at 128). Faces of zero area beside
// a border or a non-manifold edge, or whose flip would make an edge twice, are removed.
FlatFaces MendFlatFaces(Mesh &mesh, double flat) {
  auto isFlat = [flat](const Face &f) {  // twice the area over the longest edge, at most `flat`
    const double longest = std::max({vcg::Distance(f.cP(0), f.cP(1)), vcg::Distance(f.cP(1), f.cP(2)),
                                      vcg::Distance(f.cP(2), f.cP(0))});
    return ((f.cP(1) - f.cP(0)) ^ (f.cP(2) - f.cP(0))).Norm() <= flat * longest;
  };
  auto index = [&](const Face &f, int c) { return int(vcg::tri::Index(mesh, f.cV(c))); };
  FlatFaces done;
  // A round welds or flips each flat face whose neighbours no other mend of the round changes;
  // a flip can leave a flat face (the neighbour was flat too), so rounds go on while they mend.
  constexpr int kRounds = 8;
  for (int round = 0; round < kRounds; ++round) {
    const EdgeFaces edgeFaces(mesh);
    auto closedRound = [&](const Face &f) {
      for (int e = 0; e < 3; ++e)
        if (edgeFaces.Around(index(f, e), index(f, (e + 1) % 3)).size() != 2) return false;
      return true;
    };
    UnionFind into(int(mesh.vert.size()));
    std::vector<char> touched(mesh.face.size(), 0), joined(mesh.vert.size(), 0);  // joined: ends of an edge a flip made this round
    int welds = 0, flips = 0;
    for (std::size_t n = 0; n < mesh.face.size(); ++n) {
      Face &f = mesh.face[n];
      if (f.IsD() || touched[n] || !isFlat(f) || !closedRound(f)) continue;
      int shortest = 0, longest = 0;  // edges e = (e, e + 1)
      for (int e = 1; e < 3; ++e) {
        const double length = vcg::Distance(f.cP(e), f.cP((e + 1) % 3));
        if (length < vcg::Distance(f.cP(shortest), f.cP((shortest + 1) % 3))) shortest = e;
        if (length > vcg::Distance(f.cP(longest), f.cP((longest + 1) % 3))) longest = e;
      }
      if (vcg::Distance(f.cP(shortest), f.cP((shortest + 1) % 3)) <=
          std::max(flat, kNeedle * vcg::Distance(f.cP(longest), f.cP((longest + 1) % 3)))) {
        into.Merge(index(f, (shortest + 1) % 3), index(f, shortest));
        touched[n] = 1, ++welds;
        continue;
      }
      // f = (a, b, c) with c on the edge a b; g = (b, a, d) across it: (a, d, c) and (d, b, c).
      const int a = index(f, longest), b = index(f, (longest + 1) % 3);
      const EdgeFaces::Faces across = edgeFaces.Around(a, b);
      const int g = across[0] == int(n) ? across[1] : across[0];
      if (touched[g]) continue;
      Face &h = mesh.face[g];
      int d = 0;
      while (h.cV(d) == f.cV(longest) || h.cV(d) == f.cV((longest + 1) % 3)) ++d;
      const int c = (longest + 2) % 3;
      // An edge c d already there (or made by another flip of this round, which the table
      // does not hold yet) would be made twice: f waits for the next round, or is removed below.
      if (h.V(d) == f.V(c) || joined[index(f, c)] || joined[index(h, d)] ||
          edgeFaces.Around(index(f, c), index(h, d)).size() > 0)
        continue;
      joined[index(f, c)] = joined[index(h, d)] = 1;
      Vertex *va = f.V(longest), *vb = f.V((longest + 1) % 3), *vc = f.V(c), *vd = h.V(d);
      const auto ta = f.WT(longest), tb = f.WT((longest + 1) % 3), tc = f.WT(c), td = h.WT(d);
      f.V(0) = va, f.V(1) = vd, f.V(2) = vc, f.WT(0) = ta, f.WT(1) = td, f.WT(2) = tc;
      h.V(0) = vd, h.V(1) = vb, h.V(2) = vc, h.WT(0) = td, h.WT(1) = tb, h.WT(2) = tc;
      touched[n] = touched[g] = 1, ++flips;
    }
    if (welds > 0) {  // each welded corner into its set's first; faces left repeating a corner go, and the corners welded away
      for (Face &f : mesh.face)
        if (!f.IsD())
          for (int c = 0; c < 3; ++c) f.V(c) = &mesh.vert[into.Find(index(f, c))];
      vcg::tri::Clean<Mesh>::RemoveDegenerateFace(mesh);
      vcg::tri::Clean<Mesh>::RemoveDuplicateFace(mesh);
      vcg::tri::Clean<Mesh>::RemoveUnreferencedVertex(mesh);
    }
    done.welded += welds, done.flipped += flips;
    if (welds + flips == 0) break;
  }
  done.orphans = RemoveFacesWhere(mesh, isFlat, done.removed);
  return done;
}

} // namespace

void PrepareMesh(Mesh &mesh, const std::string &role, std::vector<std::string> &notes) {
  using Clean = vcg::tri::Clean<Mesh>;
  if (mesh.fn == 0)
    throw Error("the " + role + " mesh has no faces (" + std::to_string(mesh.vn) + " vertices): the map needs a " +
                "triangle mesh; pick another layer or rebuild a surface from the points first");

  // 1, 2.
  Note(notes, role, Clean::RemoveDegenerateFace(mesh), "faces that repeat a vertex removed");
  Note(notes, role, Clean::RemoveUnreferencedVertex(mesh), "vertices that no face uses removed");

  // 3.
  int nonFinite = 0;
  long first = -1;
  for (const Vertex &v : mesh.vert)
    if (!v.IsD() && !Finite(v.cP()) && nonFinite++ == 0) first = long(vcg::tri::Index(mesh, v));
  if (nonFinite > 0)
    throw Error("the " + role + " mesh has " + std::to_string(nonFinite) + " vertices with a NaN or infinite " +
                "coordinate (the first is vertex " + std::to_string(first) + "): remove or repair them and apply " +
                "the filter again");
  if (mesh.fn == 0)
    throw Error("every face of the " + role + " mesh repeats a vertex: the map needs a triangle mesh");
  vcg::tri::UpdateBounding<Mesh>::Box(mesh);
  const double diag = mesh.bbox.Diag();
  if (!(diag > 0)) throw Error("the " + role + " mesh has no extent: all its vertices lie at one point");

  // 4.
  const int welded = Weld(mesh);
  Note(notes, role, welded, "vertices at the same place as another welded");
  if (welded > 0) {
    const int degenerate = Clean::RemoveDegenerateFace(mesh);
    Note(notes, role, Clean::RemoveDuplicateFace(mesh) + degenerate, "faces made twice by the welding removed");
  }

  // 5.
  const FlatFaces flat = MendFlatFaces(mesh, kFlatHeight * diag);
  if (mesh.fn == 0)
    throw Error("every face of the " + role + " mesh has zero area (its vertices lie on lines or points): the " +
                "map needs a surface");
  Note(notes, role, flat.welded + flat.flipped,
       "faces of zero area mended where the surface closes round them (" + std::to_string(flat.welded) +
           " by welding corners at one place, " + std::to_string(flat.flipped) + " by flipping the edge a corner lies on)");
  Note(notes, role, flat.removed, "faces of zero area removed" +
                                      (flat.orphans > 0 ? " (with " + std::to_string(flat.orphans) + " vertices only they used)"
                                                        : std::string()));

  // 6.
  Note(notes, role, OrientCoherently(mesh), "faces turned to agree with their neighbours");
  Note(notes, role, OrientOutward(mesh), "faces of parts that pointed inward turned outward");

  if (std::size_t(mesh.vn) != mesh.vert.size() || std::size_t(mesh.fn) != mesh.face.size())
    vcg::tri::Allocator<Mesh>::CompactEveryVector(mesh);
  vcg::tri::UpdateBounding<Mesh>::Box(mesh);
}

void CheckAnchors(const std::vector<AnchorPair> &anchors) {
  Box3 box[2];
  for (const AnchorPair &a : anchors) {
    for (const auto &[p, side] : {std::pair(a.source, "source"), std::pair(a.target, "target")})
      if (!Finite(p))
        throw Error("anchor '" + a.name + "' has a NaN or infinite coordinate on the " + side +
                    ": correct it in the picked-points file or give another point");
    box[0].Add(a.source), box[1].Add(a.target);
  }
  for (int side = 0; side < 2; ++side) {
    auto at = [&](std::size_t n) { return side ? anchors[n].target : anchors[n].source; };
    for (std::size_t i = 0; i < anchors.size(); ++i)
      for (std::size_t j = i + 1; j < anchors.size(); ++j)
        if (vcg::Distance(at(i), at(j)) <= 1e-9 * box[side].Diag())
          throw Error("anchors '" + anchors[i].name + "' and '" + anchors[j].name + "' lie at the same point of the " +
                      (side ? "target" : "source") + ": give each anchor its own place, or remove one");
  }
}

} // namespace eulermap
