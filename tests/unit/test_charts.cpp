// Texture coordinates and their charts (charts.h) on meshes whose seams are known: the
// torus of MakeTorus (u, v wrapping from 1 to 0: one chart, two seam circles) and a sphere
// without coordinates.
#include "core/charts.h"
#include "tests/support/meshes.h"

#include <gtest/gtest.h>

using namespace eulermap;
using namespace eulermap::testing;

namespace {

constexpr int kRing = 24, kTube = 12;

// The number of charts: pieces of faces connected across edges where coordinates continue.
int Charts(const Mesh &m, const TexCoordSeams &seams) {
  std::vector<char> seen(m.face.size(), 0);
  int charts = 0;
  for (std::size_t start = 0; start < m.face.size(); ++start) {
    if (m.face[start].IsD() || seen[start]) continue;
    ++charts;
    std::vector<int> stack{int(start)};
    seen[start] = 1;
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      for (int g : seams.across[f])
        if (g >= 0 && !seen[g]) seen[g] = 1, stack.push_back(g);
    }
  }
  return charts;
}

// Face edges with no continuation (seams and borders).
int Cut(const TexCoordSeams &seams) {
  int cut = 0;
  for (const auto &across : seams.across)
    for (int g : across) cut += g < 0;
  return cut;
}

TEST(Charts, DetectsWhichCoordinatesAMeshCarries) {
  Mesh wedge, vertex, none;
  MakeTorus(wedge, Point3(0, 0, 0), 1, 0.4, kRing, kTube, TexCoordKind::PerWedge);
  MakeTorus(vertex, Point3(0, 0, 0), 1, 0.4, kRing, kTube, TexCoordKind::PerVertex);
  MakeSphere(none, Point3(0, 0, 0), 1, 3);
  EXPECT_EQ(DetectTexCoords(wedge), TexCoordKind::PerWedge);
  EXPECT_EQ(DetectTexCoords(vertex), TexCoordKind::PerVertex);
  EXPECT_EQ(DetectTexCoords(none), TexCoordKind::None);
}

TEST(Charts, CoordinatesAreTheTorusAnglesInTheUnitSquare) {
  Mesh torus;
  MakeTorus(torus, Point3(0, 0, 0), 1, 0.4, kRing, kTube, TexCoordKind::PerWedge);
  for (const Face &f : torus.face)
    for (int c = 0; c < 3; ++c) {
      const vcg::TexCoord2d t = CornerTexCoord(f, c, TexCoordKind::PerWedge);
      EXPECT_GE(t.U(), 0);
      EXPECT_LE(t.U(), 1);
      EXPECT_GE(t.V(), 0);
      EXPECT_LE(t.V(), 1);
    }
}

TEST(Charts, TheClosedTorusIsOneChartCutAlongItsTwoSeamCircles) {
  Mesh torus;
  MakeTorus(torus, Point3(0, 0, 0), 1, 0.4, kRing, kTube, TexCoordKind::PerWedge);
  const TexCoordSeams seams = FindSeams(torus, TexCoordKind::PerWedge);
  EXPECT_EQ(Charts(torus, seams), 1);
  // The seam circles have kTube and kRing edges, each with a face on either side.
  EXPECT_EQ(Cut(seams), 2 * (kRing + kTube));
}

TEST(Charts, TheOpenTorusIsOneChartBorderedByItsSeams) {
  Mesh torus;
  MakeTorus(torus, Point3(0, 0, 0), 1, 0.4, kRing, kTube, TexCoordKind::PerVertex);
  const TexCoordSeams seams = FindSeams(torus, TexCoordKind::PerVertex);
  EXPECT_EQ(Charts(torus, seams), 1);
  EXPECT_EQ(Cut(seams), 2 * (kRing + kTube));  // now borders: the seams' vertices are doubled
}

TEST(Charts, AMeshWithoutCoordinatesHasNoSeams) {
  Mesh sphere;
  MakeSphere(sphere, Point3(0, 0, 0), 1, 3);
  EXPECT_EQ(Cut(FindSeams(sphere, TexCoordKind::PerWedge)), 0);  // every coordinate (0, 0)
}

} // namespace
