#include "charts.h"

#include <algorithm>

namespace eulermap {

TexCoordKind DetectTexCoords(const Mesh &m) {
  for (const Face &f : m.face)
    if (!f.IsD())
      for (int c = 0; c < 3; ++c)
        if (f.cWT(c).P() != vcg::Point2d(0, 0)) return TexCoordKind::PerWedge;
  for (const Vertex &v : m.vert)
    if (!v.IsD() && v.cT().P() != vcg::Point2d(0, 0)) return TexCoordKind::PerVertex;
  return TexCoordKind::None;
}

vcg::TexCoord2d CornerTexCoord(const Face &f, int c, TexCoordKind kind) {
  return kind == TexCoordKind::PerVertex ? f.cV(c)->cT() : f.cWT(c);
}

TexCoordSeams FindSeams(const Mesh &m, TexCoordKind kind) {
  const int faces = int(m.face.size());
  // Every face edge, keyed by its two vertices (smaller index first); equal keys are the
  // faces that share the edge.
  struct HalfEdge {
    int lo, hi, face, edge;
  };
  std::vector<HalfEdge> edges;
  edges.reserve(3 * std::size_t(faces));
  for (int f = 0; f < faces; ++f) {
    if (m.face[f].IsD()) continue;
    for (int e = 0; e < 3; ++e) {
      const int a = int(vcg::tri::Index(m, m.face[f].cV(e))), b = int(vcg::tri::Index(m, m.face[f].cV((e + 1) % 3)));
      edges.push_back({std::min(a, b), std::max(a, b), f, e});
    }
  }
  std::sort(edges.begin(), edges.end(),
            [](const HalfEdge &x, const HalfEdge &y) { return x.lo != y.lo ? x.lo < y.lo : x.hi < y.hi; });

  // The coordinate a face has at one of its vertices, with the texture index.
  auto at = [&](int f, int vertex) {
    const Face &face = m.face[f];
    for (int c = 0; c < 3; ++c)
      if (int(vcg::tri::Index(m, face.cV(c))) == vertex) return CornerTexCoord(face, c, kind);
    return vcg::TexCoord2d();
  };
  auto continuous = [&](const HalfEdge &x, const HalfEdge &y) {
    for (int v : {x.lo, x.hi}) {
      const vcg::TexCoord2d s = at(x.face, v), t = at(y.face, v);
      if (s.P() != t.P() || s.N() != t.N()) return false;
    }
    return true;
  };

  TexCoordSeams seams;
  seams.across.assign(faces, {-1, -1, -1});
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) ++j;
    // The faces around one edge (two on a manifold edge): each continues into the first
    // other one whose coordinates agree.
    for (std::size_t a = i; a < j; ++a)
      for (std::size_t b = i; b < j; ++b) {
        int &across = seams.across[edges[a].face][edges[a].edge];
        if (a != b && across < 0 && continuous(edges[a], edges[b])) across = edges[b].face;
      }
    i = j;
  }
  return seams;
}

} // namespace eulermap
