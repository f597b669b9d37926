// Unit tests of red_black.h: the colour-split storage of the multigrid's levels.
#include "core/red_black.h"

#include <gtest/gtest.h>

#include <set>

namespace eulermap {
namespace {

// Odd and even sizes on each axis, so that rows start with either colour.
const vcg::Point3i kDims(7, 4, 5);

// Every real node has its own position in its colour's arrays, inside the arrays, and the
// runs of ForEachRun visit each real node once, at the position Position gives.
TEST(RedBlack, RunsVisitEveryNodeOnceAtItsPosition) {
  const RedBlackLayout layout(kDims);
  std::set<std::pair<int, std::size_t>> seen;
  int visits = 0;
  ForEachRun(layout, 0, 1, [&](int j, int k, int c, const RedBlackLayout::Run &run, std::size_t row) {
    for (int n = 0; n < run.count; ++n) {
      const int i = run.firstI + 2 * n;
      ASSERT_LT(i, kDims[0]);
      EXPECT_EQ(RedBlackLayout::Colour(i, j, k), c);
      EXPECT_EQ(layout.Position(i, j, k), run.first + n);
      EXPECT_LT(run.first + n, layout.Positions());
      EXPECT_EQ(row + i, std::size_t(i + kDims[0] * (j + kDims[1] * k)));
#pragma omp critical
      {
        seen.insert({c, run.first + n});
        ++visits;
      }
    }
  });
  EXPECT_EQ(visits, int(layout.Nodes()));
  EXPECT_EQ(seen.size(), layout.Nodes());
}

// NeighbourSum at a node adds the other colour's values of its six neighbours; a neighbour
// off the box reads a ghost, which holds 0.
TEST(RedBlack, NeighbourSumAddsTheSixNeighboursAndGhostsAreZero) {
  const RedBlackLayout layout(kDims);
  RedBlackArrays<1, double> v;
  v.Resize(layout);
  auto value = [](int i, int j, int k) { return 1.0 + i + 10.0 * j + 100.0 * k; };
  for (int k = 0; k < kDims[2]; ++k)
    for (int j = 0; j < kDims[1]; ++j)
      for (int i = 0; i < kDims[0]; ++i) v.c[RedBlackLayout::Colour(i, j, k)][0][layout.Position(i, j, k)] = value(i, j, k);
  const long hy = layout.RowStride(), hz = layout.PlaneStride();
  for (int k = 0; k < kDims[2]; ++k)
    for (int j = 0; j < kDims[1]; ++j)
      for (int c = 0; c < 2; ++c) {
        const RedBlackLayout::Run run = layout.RowRun(c, j, k);
        for (int n = 0; n < run.count; ++n) {
          const int i = run.firstI + 2 * n;
          double expected = 0;
          const int d[6][3] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
          for (const auto &o : d) {
            const int a = i + o[0], b = j + o[1], e = k + o[2];
            if (a >= 0 && b >= 0 && e >= 0 && a < kDims[0] && b < kDims[1] && e < kDims[2]) expected += value(a, b, e);
          }
          EXPECT_EQ(NeighbourSum(v.c[1 - c][0].data() + run.first, n, run.west, hy, hz), expected)
              << "node " << i << " " << j << " " << k;
          EXPECT_EQ(layout.NeighbourCount(i, j, k) == 6, i > 0 && j > 0 && k > 0 && i + 1 < kDims[0] &&
                                                             j + 1 < kDims[1] && k + 1 < kDims[2]);
        }
      }
}

} // namespace
} // namespace eulermap
