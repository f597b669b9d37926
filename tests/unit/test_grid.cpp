// The grid (grid.h): node positions, storage indices and fractional coordinates agree; the
// enclosing grid holds the box with its padding, has the asked cells on the longest side and
// is centred on the box; the grid with given node counts has them and is the finest that
// holds the box.
#include "core/grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace eulermap;

namespace {

const Box3 kBox(Point3(-1.5, 0.25, 2), Point3(2.5, 1.25, 4));  // 4 x 1 x 2

// Whether `inner` lies inside `outer` with at least `margin` on every side.
bool HoldsWithMargin(const Box3 &outer, const Box3 &inner, double margin) {
  for (int a = 0; a < 3; ++a)
    if (inner.min[a] - outer.min[a] < margin || outer.max[a] - inner.max[a] < margin) return false;
  return true;
}

TEST(Grid, IndexPositionAndGridCoordinatesRoundTrip) {
  Grid g;
  g.origin = Point3(-1, 2, 0.5);
  g.h = 0.25;
  g.dims = vcg::Point3i(5, 7, 3);
  EXPECT_EQ(g.NodeCount(), 105u);
  std::size_t expected = 0;
  g.ForEachNode([&](int i, int j, int k, std::size_t n) {
    EXPECT_EQ(n, expected++) << "storage order";
    EXPECT_EQ(n, g.Index(i, j, k));
    const Point3 c = g.ToGrid(g.Node(i, j, k));
    EXPECT_LT(vcg::Distance(c, Point3(i, j, k)), 1e-12);
    const std::size_t back = std::size_t(n % 5), row = std::size_t(n / 5 % 7), slab = std::size_t(n / 35);
    EXPECT_EQ(vcg::Point3i(int(back), int(row), int(slab)), vcg::Point3i(i, j, k));
  });
  EXPECT_EQ(expected, g.NodeCount());
  EXPECT_EQ(g.Bounds().min, g.Node(0, 0, 0));
  EXPECT_EQ(g.Bounds().max, g.Node(4, 6, 2));
  EXPECT_LT(vcg::Distance(g.ToGrid(Point3(-0.875, 2.5, 0.5)), Point3(0.5, 2, 0)), 1e-12);  // between nodes
}

TEST(Grid, TheEnclosingGridHoldsTheBoxWithItsPadding) {
  for (int cells : {8, 24, 64})
    for (double pad : {0.0, 1.0, 3.0}) {
      const Grid g = Grid::Enclosing(kBox, cells, pad);
      EXPECT_TRUE(HoldsWithMargin(g.Bounds(), kBox, pad * g.h - 1e-12)) << cells << " cells, pad " << pad;
      EXPECT_LT(vcg::Distance(g.Bounds().Center(), kBox.Center()), 1e-12);
      // The box's longest side (x) spans cells - 2 pad cells; the grid adds the padding.
      EXPECT_NEAR(g.h, 4.0 / (cells - 2 * pad), 1e-12);
      EXPECT_NEAR(g.dims.X() - 1, cells, 1) << pad;  // one more where rounding tips the ceiling
      for (int a = 1; a < 3; ++a) EXPECT_LE((g.dims[a] - 1) * g.h, kBox.Dim()[a] + 2 * pad * g.h + g.h + 1e-12);
    }
}

TEST(Grid, TheDefaultPaddingIsThreeCells) {
  const Grid g = Grid::Enclosing(kBox, 64);
  EXPECT_TRUE(HoldsWithMargin(g.Bounds(), kBox, 3 * g.h - 1e-12));
  EXPECT_FALSE(HoldsWithMargin(g.Bounds(), kBox, 3.5 * g.h));
}

TEST(Grid, GivenNodeCountsAreKeptAndTheBoxFitsTightly) {
  const vcg::Point3i nodes(40, 20, 30);
  const Grid g = Grid::WithNodes(kBox, nodes, 3);
  EXPECT_EQ(g.dims, nodes);
  EXPECT_TRUE(HoldsWithMargin(g.Bounds(), kBox, 3 * g.h - 1e-12));
  EXPECT_LT(vcg::Distance(g.Bounds().Center(), kBox.Center()), 1e-12);
  // The finest that fits: on one axis the box and its padding fill the nodes exactly.
  double tightest = 1e300;
  for (int a = 0; a < 3; ++a) tightest = std::min(tightest, (nodes[a] - 1) * g.h - kBox.Dim()[a] - 6 * g.h);
  EXPECT_NEAR(tightest, 0, 1e-12);
}

TEST(Grid, CoordinatesInvertIndex) {
  Grid g;
  g.dims = vcg::Point3i(5, 7, 3);
  g.ForEachNode([&](int i, int j, int k, std::size_t n) { EXPECT_EQ(g.Coordinates(n), vcg::Point3i(i, j, k)) << n; });
}

} // namespace
