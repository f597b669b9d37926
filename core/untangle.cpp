#include "untangle.h"

#include "threads.h"

#include <vcg/complex/algorithms/update/normal.h>

namespace eulermap {

namespace {
// Marks the vertices of faces whose normal opposes the target's at their centroid.
bool MarkFlipped(Mesh &m, const ClosestPoint &target, std::vector<char> &marked) {
  vcg::tri::UpdateNormal<Mesh>::PerFaceNormalized(m);
  bool any = false;
  for (const Face &f : m.face) {
    if (f.IsD()) continue;
    const ClosestHit hit = target.Query(vcg::Barycenter(f));
    if (hit.face && f.cN() * hit.face->cN() < 0) {
      any = true;
      for (int c = 0; c < 3; ++c) marked[vcg::tri::Index(m, f.cV(c))] = 1;
    }
  }
  return any;
}
} // namespace

int Untangle(Mesh &mapped, const ClosestPoint &target, int rounds, int rings) {
  const std::size_t n = mapped.vert.size();
  std::vector<std::vector<int>> neighbours(n);
  for (const Face &f : mapped.face)
    if (!f.IsD())
      for (int c = 0; c < 3; ++c) {
        const int a = int(vcg::tri::Index(mapped, f.cV(c))), b = int(vcg::tri::Index(mapped, f.cV((c + 1) % 3)));
        neighbours[a].push_back(b);
        neighbours[b].push_back(a);
      }
  std::vector<char> ever(n, 0);
  for (int round = 0; round < rounds; ++round) {
    std::vector<char> marked(n, 0);
    if (!MarkFlipped(mapped, target, marked)) break;
    for (int r = 0; r < rings; ++r) {
      std::vector<char> grown = marked;
      for (std::size_t v = 0; v < n; ++v)
        if (marked[v])
          for (int w : neighbours[v]) grown[w] = 1;
      marked.swap(grown);
    }
    std::vector<Point3> next(n);
#pragma omp parallel for schedule(dynamic, 64) num_threads(Threads())
    for (long v = 0; v < long(n); ++v) {
      next[v] = mapped.vert[v].cP();
      if (!marked[v] || neighbours[v].empty()) continue;
      Point3 mean(0, 0, 0);
      for (int w : neighbours[v]) mean += mapped.vert[w].cP();
      next[v] = target.Query(mean / double(neighbours[v].size())).point;
    }
    for (std::size_t v = 0; v < n; ++v) {
      ever[v] |= marked[v];
      mapped.vert[v].P() = next[v];
    }
  }
  return int(std::count(ever.begin(), ever.end(), 1));
}

} // namespace eulermap
