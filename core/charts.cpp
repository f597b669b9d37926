#include "charts.h"

#include "edge_faces.h"
#include "union_find.h"

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
  const EdgeFaces edgeFaces(m);
  // The coordinate a face has at one of its vertices, with the texture index.
  auto at = [&](int f, int vertex) {
    const Face &face = m.face[f];
    for (int c = 0; c < 3; ++c)
      if (int(vcg::tri::Index(m, face.cV(c))) == vertex) return CornerTexCoord(face, c, kind);
    return vcg::TexCoord2d();
  };
  auto continuous = [&](int f, int g, int a, int b) {
    for (int v : {a, b}) {
      const vcg::TexCoord2d s = at(f, v), t = at(g, v);
      if (s.P() != t.P() || s.N() != t.N()) return false;
    }
    return true;
  };

  // Each face continues across an edge into the first other face around it (two on a
  // manifold edge) whose coordinates agree.
  TexCoordSeams seams;
  seams.across.assign(m.face.size(), {-1, -1, -1});
  for (int f = 0; f < int(m.face.size()); ++f) {
    if (m.face[f].IsD()) continue;
    for (int e = 0; e < 3; ++e) {
      const int a = int(vcg::tri::Index(m, m.face[f].cV(e))), b = int(vcg::tri::Index(m, m.face[f].cV((e + 1) % 3)));
      for (int g : edgeFaces.Around(a, b))
        if (g != f && continuous(f, g, a, b)) {
          seams.across[f][e] = g;
          break;
        }
    }
  }
  return seams;
}

std::vector<int> Charts(const TexCoordSeams &seams) {
  UnionFind charts(int(seams.across.size()));
  for (std::size_t f = 0; f < seams.across.size(); ++f)
    for (int g : seams.across[f])
      if (g >= 0) charts.Merge(int(f), g);
  std::vector<int> chart(seams.across.size());
  for (std::size_t f = 0; f < chart.size(); ++f) chart[f] = charts.Find(int(f));
  return chart;
}

} // namespace eulermap
