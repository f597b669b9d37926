// Saddles of the velocity field (saddle.h) on linear fields V(x) = A (x - c), whose only
// zero is c and whose trilinear interpolant is exact: the saddle-type zeros are found where
// they are, with their kind; sinks, sources, spirals and nearly degenerate zeros are not.
#include "core/saddle.h"
#include "tests/support/fields.h"

#include <gtest/gtest.h>

using namespace eulermap;
using namespace eulermap::testing;

namespace {

const Point3 kInsideACell(0.13, -0.21, 0.07);  // not on a node
const double kOneExpanding[3][3] = {{1, 0.3, 0}, {0, -1, 0.2}, {0, 0, -0.5}};
const double kTwoExpanding[3][3] = {{1, 0, 0}, {0, 0.5, 0}, {0.3, 0, -2}};

TEST(Saddle, ALinearSaddleIsFoundAtItsZeroWithItsKind) {
  for (auto *A : {kOneExpanding, kTwoExpanding}) {
    const std::vector<Saddle> s = FindSaddles(LinearField(A, kInsideACell));
    ASSERT_EQ(s.size(), 1u);
    EXPECT_LT(vcg::Distance(s[0].position, kInsideACell), 1e-9);
    EXPECT_EQ(s[0].expandingDirections, A == kOneExpanding ? 1 : 2);
  }
}

TEST(Saddle, SinksSourcesAndSpiralsAreNoSaddles) {
  const double sink[3][3] = {{-1, 0, 0}, {0, -2, 0}, {0, 0, -1}};
  const double source[3][3] = {{1, 0, 0}, {0, 2, 0}, {0, 0, 1}};
  const double spiral[3][3] = {{-0.1, -1, 0}, {1, -0.1, 0}, {0, 0, -1}};  // a rotation about a sink
  for (auto *A : {sink, source, spiral}) EXPECT_TRUE(FindSaddles(LinearField(A, kInsideACell)).empty());
}

// A rate 1% of the largest (below kMinRate), as along a ring of zeros: no saddle.
TEST(Saddle, ANearlyDegenerateZeroIsNoSaddle) {
  const double ring[3][3] = {{1, 0, 0}, {0, 0.01, 0}, {0, 0, -1}};
  EXPECT_TRUE(FindSaddles(LinearField(ring, kInsideACell)).empty());
}

// Found from each of the node's 8 cells, it is one saddle.
TEST(Saddle, ASaddleOnAGridNodeIsFoundOnce) {
  const Point3 node(-1 + 7 * 2.0 / 15, -1 + 2.0 / 15, -1 + 9 * 2.0 / 15);
  EXPECT_EQ(FindSaddles(LinearField(kOneExpanding, node)).size(), 1u);
}

// The count of eigenvalues with positive real part, or -1 where one real part is under
// kMinRate times the largest modulus.
TEST(Saddle, ExpandingDirectionsCountsPositiveRealPartsOfNonDegenerateJacobians) {
  const double sink[3][3] = {{-1, 0, 0}, {0, -2, 0}, {0, 0, -3}};
  const double source[3][3] = {{1, 0, 0}, {0, 2, 0}, {0, 0, 3}};
  const double spiralOut[3][3] = {{0.5, -1, 0}, {1, 0.5, 0}, {0, 0, -1}};  // complex pair, real part 0.5
  const double degenerate[3][3] = {{1, 0, 0}, {0, -1, 0}, {0, 0, 0.05}};  // 0.05 < kMinRate
  EXPECT_EQ(ExpandingDirections(sink), 0);
  EXPECT_EQ(ExpandingDirections(source), 3);
  EXPECT_EQ(ExpandingDirections(kOneExpanding), 1);
  EXPECT_EQ(ExpandingDirections(kTwoExpanding), 2);
  EXPECT_EQ(ExpandingDirections(spiralOut), 2);
  EXPECT_EQ(ExpandingDirections(degenerate), -1);
}

} // namespace
