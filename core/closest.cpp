// eulermap::ClosestPoint — nearest surface point: a bounding-volume tree over the faces,
// searched nearest-first, with vcglib's point–triangle distance at the leaves.
//
// Why not vcglib's GridStaticPtr with tri::GetClosestFaceBase (what DESIGN.md suggests):
// - Thread safety. GetClosestFaceBase hard-wires a tri::FaceTmark, which writes the mesh's
//   mark counter and every visited face's mark, so concurrent queries race. vcglib's
//   other indexes do the same (Octree: IncrementMark) or write into their nodes during a
//   query (AABBBinaryTree: ScalarValue()).
// - Queries far from the surface. vcg::GridClosest starts at a radius of one voxel
//   diagonal, grows it by one voxel diagonal per round until a face turns up and walks
//   every cell of the cube each round: O((D/voxel)^4) cell visits at distance D, then
//   every face in the cube of half-side D. SDF grids are mostly such nodes: on
//   camelhead.off (22.7k faces) a 64^3 grid took ~750 us per node through GridClosest,
//   and still ~350 us with a search that starts at the distance to the index's box and
//   grows geometrically (the faces in the cube dominate). This tree: ~4-7 us per node.
// The point–triangle distance is vcglib's (face::PointDistanceBase, the one
// GetClosestFaceBase uses), so results are the same as vcglib's up to ties.
#include "closest.h"

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/simplex/face/distance.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

namespace eulermap {

namespace {

constexpr int kLeafSize = 4;  // faces per leaf

} // namespace

Point3 Barycentric(const Point3 &a, const Point3 &b, const Point3 &c, const Point3 &p) {
  const Point3 e0 = b - a, e1 = c - a, d = p - a;
  const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1);
  const double d20 = d.dot(e0), d21 = d.dot(e1);
  const double denom = d00 * d11 - d01 * d01;
  if (!(denom > 1e-24 * std::max(d00 * d11, 1e-300))) {
    const double da = (p - a).SquaredNorm(), db = (p - b).SquaredNorm(), dc = (p - c).SquaredNorm();
    if (da <= db && da <= dc) return Point3(1, 0, 0);
    return db <= dc ? Point3(0, 1, 0) : Point3(0, 0, 1);
  }
  const double l1 = (d11 * d20 - d01 * d21) / denom;
  const double l2 = (d00 * d21 - d01 * d20) / denom;
  return Point3(1 - l1 - l2, l1, l2);
}

// Faces in tree order; nodes stored depth-first (the left child follows its parent,
// `right` indexes the right child, -1 for a leaf). Read-only once built.
struct ClosestPoint::Tree {
  struct Node {
    Point3 lo, hi;  // box of the node's faces
    int first = 0, count = 0;
    int right = -1;
  };
  std::vector<Face *> faces;
  std::vector<Node> nodes;

  // in:  the live faces of a mesh
  // out: the tree, by median splits of the face centroids along their box's longest axis.
  explicit Tree(std::vector<Face *> f) : faces(std::move(f)) {
    centroid.resize(faces.size());
    for (std::size_t i = 0; i < faces.size(); ++i)
      centroid[i] = (faces[i]->cP(0) + faces[i]->cP(1) + faces[i]->cP(2)) / 3.0;
    order.resize(faces.size());
    std::iota(order.begin(), order.end(), 0);
    if (!faces.empty()) Build(0, int(faces.size()));
    std::vector<Face *> sorted(faces.size());
    for (std::size_t i = 0; i < faces.size(); ++i) sorted[i] = faces[order[i]];
    faces.swap(sorted);
    centroid.clear();
    order.clear();
  }

  // Squared distance from p to the node's box (0 inside).
  static double BoxDistance2(const Node &n, const Point3 &p) {
    double s = 0;
    for (int a = 0; a < 3; ++a) {
      const double e = std::max({n.lo[a] - p[a], 0.0, p[a] - n.hi[a]});
      s += e * e;
    }
    return s;
  }

  // in:  p; best — the bail-out distance (no face at or beyond it is reported); among —
  //      the faces to consider (null: all)
  // out: the nearest face (nullptr if none is nearer than best), best and closest updated.
  //      Nodes are visited nearest box first and skipped when their box is not nearer
  //      than the best face so far.
  Face *Nearest(const Point3 &p, double &best, Point3 &closest, const std::function<bool(const Face &)> *among) const {
    if (nodes.empty()) return nullptr;
    struct Entry {
      int node;
      double d2;
    };
    Entry stack[128];  // median splits: depth <= log2(#faces) + 1, one pending sibling per level
    int top = 0;
    stack[top++] = {0, BoxDistance2(nodes[0], p)};
    Face *winner = nullptr;
    Point3 q;
    while (top > 0) {
      const Entry e = stack[--top];
      if (e.d2 >= best * best) continue;
      const Node &n = nodes[e.node];
      if (n.right < 0) {
        for (int i = n.first; i < n.first + n.count; ++i)
          if ((!among || (*among)(*faces[i])) && vcg::face::PointDistanceBase(*faces[i], p, best, q)) {
            winner = faces[i];
            closest = q;
          }
        continue;
      }
      const int l = e.node + 1, r = n.right;
      const double dl = BoxDistance2(nodes[l], p), dr = BoxDistance2(nodes[r], p);
      if (dl <= dr) {  // the nearer child goes on top
        stack[top++] = {r, dr};
        stack[top++] = {l, dl};
      } else {
        stack[top++] = {l, dl};
        stack[top++] = {r, dr};
      }
    }
    return winner;
  }

 private:
  std::vector<Point3> centroid;  // build-time only
  std::vector<int> order;

  int Build(int begin, int end) {
    const int id = int(nodes.size());
    nodes.emplace_back();
    Box3 box, cbox;
    for (int i = begin; i < end; ++i) {
      const Face *f = faces[order[i]];
      for (int v = 0; v < 3; ++v) box.Add(f->cP(v));
      cbox.Add(centroid[order[i]]);
    }
    nodes[id].lo = box.min;
    nodes[id].hi = box.max;
    nodes[id].first = begin;
    nodes[id].count = end - begin;
    if (end - begin <= kLeafSize) return id;
    const Point3 dim = cbox.Dim();
    const int axis = dim[0] >= dim[1] ? (dim[0] >= dim[2] ? 0 : 2) : (dim[1] >= dim[2] ? 1 : 2);
    const int mid = begin + (end - begin) / 2;
    std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                     [&](int a, int b) { return centroid[a][axis] < centroid[b][axis]; });
    Build(begin, mid);
    const int right = Build(mid, end);
    nodes[id].right = right;
    return id;
  }
};

// in:  mesh — a triangle mesh; its bounding box and (normalized) face normals are
//      updated here, as vcglib's point–face distance needs the normals.
// out: the tree over the mesh's live faces (empty when it has none).
ClosestPoint::ClosestPoint(Mesh &mesh) : mesh_(mesh) {
  vcg::tri::UpdateBounding<Mesh>::Box(mesh_);
  vcg::tri::UpdateNormal<Mesh>::PerFaceNormalized(mesh_);
  std::vector<Face *> faces;
  faces.reserve(mesh_.fn);
  for (Face &f : mesh_.face)
    if (!f.IsD()) faces.push_back(&f);
  tree_ = std::make_shared<const Tree>(std::move(faces));
}

namespace {

// in:  tree, p, best — the search radius; among — the faces to consider (null: all)
// out: the nearest point on those faces, its face, the point's barycentric coordinates in
//      that face and the distance; face == nullptr when no such face lies within best.
template <class Tree>
ClosestHit Search(const Tree &tree, const Point3 &p, double best, const std::function<bool(const Face &)> *among) {
  ClosestHit hit;
  Point3 closest(0, 0, 0);
  Face *f = tree.Nearest(p, best, closest, among);
  if (f == nullptr) return hit;
  hit.face = f;
  hit.point = closest;
  hit.distance = best;
  hit.barycentric = Barycentric(f->cP(0), f->cP(1), f->cP(2), closest);
  return hit;
}

} // namespace

// maxDist < 0: no limit. Thread-safe: reads the tree and the mesh only.
ClosestHit ClosestPoint::Query(const Point3 &p, double maxDist) const {
  return Search(*tree_, p, maxDist < 0 ? std::numeric_limits<double>::max() : maxDist, nullptr);
}

ClosestHit ClosestPoint::Query(const Point3 &p, const std::function<bool(const Face &)> &among) const {
  return Search(*tree_, p, std::numeric_limits<double>::max(), &among);
}

} // namespace eulermap
