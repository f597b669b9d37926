#include "untangle.h"

#include "parallel.h"

#include <vcg/complex/algorithms/update/normal.h>

namespace eulermap {

namespace {
// Whether face f's normal opposes the target's at its centroid (f's normal updated).
bool Flipped(Face &f, const ClosestPoint &target) {
  f.N() = vcg::TriangleNormal(f).Normalize();
  const ClosestHit hit = target.Query(vcg::Barycenter(f));
  return hit.face && f.cN() * hit.face->cN() < 0;
}
} // namespace

// Only the faces around a vertex that moved can change their state, so after the first
// pass over every face a round checks those alone (the same rounds as checking all: a
// fold of a few hundred faces on a 100k-face map no longer costs 100k closest-point
// queries a round; TOPKIDS kid06 -> kid00, 16 anchors: 6 s a call, docs/NOTES.md).
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
  for (int round = 0; round < rounds; ++round) {
    ParallelFor(faces, [&](long f) {
      if (recheck[f] && !mapped.face[f].IsD()) flipped[f] = Flipped(mapped.face[f], target);
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
      next[v] = target.Query(mean / double(neighbours[v].size())).point;
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
