#include "untangle.h"

#include "parallel.h"

#include <vcg/complex/algorithms/update/normal.h>

namespace eulermap {

namespace {
// The nearest point on the target to p, where `onTarget` is a point of the target: no face
// farther than it can be the nearest, so the search starts with that bound (widened by a
// rounding's worth; a point not quite on the target, an empty answer, falls back to none).
ClosestHit NearestFrom(const ClosestPoint &target, const Point3 &p, const Point3 &onTarget) {
  const ClosestHit hit = target.Query(p, (p - onTarget).Norm() * (1 + 1e-9) + 1e-12);
  return hit.face ? hit : target.Query(p);
}

// Whether face f's normal opposes the target's at its centroid (f's normal updated); its
// corners lie on the target, on the target's faces `on` (nullptr: not known). Corners on one
// face put the centroid on it too.
bool Flipped(Face &f, const ClosestPoint &target, const Face *const on[3]) {
  f.N() = vcg::TriangleNormal(f).Normalize();
  const Face *under = on[0] && on[0] == on[1] && on[1] == on[2]
                          ? on[0]
                          : NearestFrom(target, vcg::Barycenter(f), f.cP(0)).face;
  return under && f.cN() * under->cN() < 0;
}
} // namespace

// Only the faces around a vertex that moved can change their state, so after the first
// pass over every face a round checks those alone (the same rounds as checking all: a
// fold of a few hundred faces on a 100k-face map no longer costs 100k closest-point
// queries a round; TOPKIDS kid06 -> kid00, 16 anchors: 6 s a call, docs/NOTES.md).
// Every query knows a point of the target near its answer (NearestFrom), and a face whose
// corners moved onto one target face needs none (Flipped): the same rounds, with the whole
// map's time on table -> chair at 48 cells 44.1 -> 32.2 s (most maps of the furniture run all
// 50 rounds, round a region the map turned over, which untangling shrinks from its rim).
int Untangle(Mesh &mapped, const ClosestPoint &target, int rounds, int rings) {
  const std::size_t n = mapped.vert.size();
  const long faces = long(mapped.face.size());
  std::vector<std::vector<int>> neighbours(n), around(n);  // vertices and faces around each vertex
  for (long f = 0; f < faces; ++f)
    if (!mapped.face[f].IsD())
      for (int c = 0; c < 3; ++c) {
        const int a = int(vcg::tri::Index(mapped, mapped.face[f].cV(c))),
                  b = int(vcg::tri::Index(mapped, mapped.face[f].cV((c + 1) % 3)));
        neighbours[a].push_back(b);
        neighbours[b].push_back(a);
        around[a].push_back(int(f));
      }
  std::vector<char> flipped(faces, 0), recheck(faces, 1);
  std::vector<char> ever(n, 0);
  std::vector<const Face *> on(n, nullptr);  // the target's face under each vertex, once it is moved
  for (int round = 0; round < rounds; ++round) {
    ParallelFor(faces, [&](long f) {
      if (!recheck[f] || mapped.face[f].IsD()) return;
      Face &face = mapped.face[f];
      const Face *const corners[3] = {on[vcg::tri::Index(mapped, face.cV(0))], on[vcg::tri::Index(mapped, face.cV(1))],
                                      on[vcg::tri::Index(mapped, face.cV(2))]};
      flipped[f] = Flipped(face, target, corners);
    });
    std::vector<char> marked(n, 0);
    bool any = false;
    for (long f = 0; f < faces; ++f)
      if (flipped[f]) {
        any = true;
        for (int c = 0; c < 3; ++c) marked[vcg::tri::Index(mapped, mapped.face[f].cV(c))] = 1;
      }
    if (!any) break;
    for (int r = 0; r < rings; ++r) {
      std::vector<char> grown = marked;
      for (std::size_t v = 0; v < n; ++v)
        if (marked[v])
          for (int w : neighbours[v]) grown[w] = 1;
      marked.swap(grown);
    }
    std::vector<Point3> next(n);
    ParallelFor(long(n), [&](long v) {
      next[v] = mapped.vert[v].cP();
      if (!marked[v] || neighbours[v].empty()) return;
      Point3 mean(0, 0, 0);
      for (int w : neighbours[v]) mean += mapped.vert[w].cP();
      const ClosestHit hit = NearestFrom(target, mean / double(neighbours[v].size()), mapped.vert[v].cP());
      next[v] = hit.point, on[v] = hit.face;
    });
    std::fill(recheck.begin(), recheck.end(), 0);
    for (std::size_t v = 0; v < n; ++v) {
      ever[v] |= marked[v];
      if (next[v] != mapped.vert[v].cP())
        for (int f : around[v]) recheck[f] = 1;
      mapped.vert[v].P() = next[v];
    }
  }
  vcg::tri::UpdateNormal<Mesh>::PerFaceNormalized(mapped);
  return int(std::count(ever.begin(), ever.end(), 1));
}

} // namespace eulermap
