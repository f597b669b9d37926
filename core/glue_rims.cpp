#include "glue_rims.h"

#include "edge_faces.h"
#include "union_find.h"

#include <vcg/space/distance3.h>
#include <vcg/space/segment3.h>

#include <algorithm>
#include <array>
#include <unordered_map>

namespace eulermap {

namespace {

using Handle = Mesh::PerVertexAttributeHandle<Point3>;

struct Loop {
  std::vector<int> vertices;
  std::vector<std::array<int, 2>> edges;
};

// The boundary loops of cut: its edges with one face, joined at their vertices.
std::vector<Loop> BoundaryLoops(const Mesh &cut) {
  const EdgeFaces faces(cut);
  std::vector<std::array<int, 2>> rim;
  for (const Face &f : cut.face)
    if (!f.IsD())
      for (int e = 0; e < 3; ++e) {
        const int a = int(vcg::tri::Index(cut, f.cV(e))), b = int(vcg::tri::Index(cut, f.cV((e + 1) % 3)));
        if (faces.Around(a, b).size() == 1) rim.push_back({a, b});
      }
  UnionFind joined(int(cut.vert.size()));
  for (const auto &e : rim) joined.Merge(e[0], e[1]);
  std::unordered_map<int, int> index;  // representative -> loop
  std::vector<Loop> loops;
  for (const auto &e : rim) {
    const auto [it, added] = index.emplace(joined.Find(e[0]), int(loops.size()));
    if (added) loops.emplace_back();
    loops[it->second].edges.push_back(e);
    loops[it->second].vertices.push_back(e[0]);
  }
  return loops;
}

double Distance(const Point3 &p, const Loop &loop, Handle &image) {
  double nearest = 1e300;
  for (int v : loop.vertices) nearest = std::min(nearest, vcg::Distance(p, image[v]));
  return nearest;
}

// The point of the loop's image nearest to p.
Point3 NearestOn(const Point3 &p, const Loop &loop, Handle &image) {
  Point3 best = p;
  double nearest = 1e300;
  for (const auto &e : loop.edges) {
    Point3 q;
    double d;
    vcg::SegmentPointDistance(vcg::Segment3<double>(image[e[0]], image[e[1]]), p, q, d);
    if (d < nearest) nearest = d, best = q;
  }
  return best;
}

} // namespace

int GlueRims(Mesh &cut, const ClosestPoint &target, const std::vector<Point3> &places, double reach) {
  if (places.empty()) return 0;
  Handle image = vcg::tri::Allocator<Mesh>::GetPerVertexAttribute<Point3>(cut, "TargetPosition");
  const std::vector<Loop> loops = BoundaryLoops(cut);
  std::vector<char> glued(loops.size(), 0);
  int pairs = 0;
  for (const Point3 &place : places) {
    int first = -1, second = -1;
    double d1 = reach, d2 = reach;
    for (int n = 0; n < int(loops.size()); ++n) {
      if (glued[n]) continue;
      const double d = Distance(place, loops[n], image);
      if (d < d1) second = first, d2 = d1, first = n, d1 = d;
      else if (d < d2) second = n, d2 = d;
    }
    if (second < 0) continue;
    glued[first] = glued[second] = 1;
    ++pairs;
    // Both rims at once, each vertex halfway to the other rim, from the images as they were.
    std::vector<std::pair<int, Point3>> moved;
    for (const auto &[from, to] : {std::pair{first, second}, std::pair{second, first}})
      for (int v : loops[from].vertices)
        moved.push_back({v, target.Query((image[v] + NearestOn(image[v], loops[to], image)) / 2).point});
    for (const auto &[v, p] : moved) image[v] = p;
  }
  return pairs;
}

} // namespace eulermap
