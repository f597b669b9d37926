// Inflate then shrink (inflate_shrink.h): the frames at t = 0 and 1 hold X0 and X1, the one
// at t* holds X1 and stays off the grid's faces; the inside set only grows before t*; a
// target part apart from the source, which the linear blend gives birth, is not born.
#include "core/inflate_shrink.h"
#include "core/zero_set_topology.h"

#include "tests/support/fields.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>

using namespace eulermap;
using eulermap::testing::Ball;
using eulermap::testing::Inside;
using eulermap::testing::Sampled;

namespace {

// X0: a ball on the left; X1: a ball overlapping it and, 0.4 beyond it, a ball that touches
// neither (the linear blend gives it birth).
struct Balls : eulermap::testing::BallScene {
  Balls() : BallScene(-0.6, 0.4, 0.9, 0.5) {}
};

TEST(InflateShrink, TheEndsHoldX0AndX1AndTheSwitchHoldsX1InsideTheGrid) {
  const Balls m;
  const InflateShrink morph(m.f0, m.f1);
  ScalarField frame;
  morph.Frame(0, frame);
  EXPECT_EQ(Inside(frame), Inside(m.f0));
  morph.Frame(1, frame);
  EXPECT_EQ(Inside(frame), Inside(m.f1));
  morph.Frame(morph.Switch(), frame);
  int x1Outside = 0, onFaces = 0;
  const Grid &g = m.g;
  for (int z = 0; z < g.dims.Z(); ++z)
    for (int y = 0; y < g.dims.Y(); ++y)
      for (int x = 0; x < g.dims.X(); ++x) {
        const std::size_t n = g.Index(x, y, z);
        x1Outside += m.f1.values[n] < 0 && frame.values[n] > 0;
        const bool face = x == 0 || y == 0 || z == 0 || x == g.dims.X() - 1 || y == g.dims.Y() - 1 || z == g.dims.Z() - 1;
        onFaces += face && frame.values[n] < 0;
      }
  EXPECT_EQ(x1Outside, 0);
  EXPECT_EQ(onFaces, 0);
  // L0: from X0 to the far side of the far ball (0.9 + 0.5 - (-1.1 + 0.6) = 1.9), within a cell.
  EXPECT_NEAR(morph.InflateLength(), 1.9, 0.1);
  EXPECT_NEAR(morph.Switch(), morph.InflateLength() / (morph.InflateLength() + morph.ShrinkLength()), 1e-12);
}

TEST(InflateShrink, TheInsideSetOnlyGrowsUntilTheSwitch) {
  const Balls m;
  const InflateShrink morph(m.f0, m.f1);
  ScalarField frame;
  std::vector<char> before = Inside(m.f0);
  int shrank = 0;
  for (int k = 1; k <= 40 && k / 40.0 <= morph.Switch(); ++k) {
    morph.Frame(k / 40.0, frame);
    const std::vector<char> now = Inside(frame);
    for (std::size_t n = 0; n < now.size(); ++n) shrank += before[n] && !now[n];
    before = now;
  }
  EXPECT_EQ(shrank, 0);
}

// Components of frame k + 1's inside set (6-connected, as zero_set_topology.h's) that hold
// no node of frame k's: parts born between the two.
int Births(const Grid &g, const std::vector<char> &before, const std::vector<char> &now) {
  std::vector<char> seen(now.size());
  int births = 0;
  for (std::size_t start = 0; start < now.size(); ++start) {
    if (!now[start] || seen[start]) continue;
    bool heldBefore = false;
    std::vector<std::size_t> stack = {start};
    seen[start] = 1;
    while (!stack.empty()) {
      const std::size_t n = stack.back();
      stack.pop_back();
      heldBefore = heldBefore || before[n];
      const int x = int(n % g.dims.X()), y = int(n / g.dims.X() % g.dims.Y()), z = int(n / (std::size_t(g.dims.X()) * g.dims.Y()));
      const int step[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
      for (const auto &d : step) {
        const int a = x + d[0], b = y + d[1], c = z + d[2];
        if (a < 0 || b < 0 || c < 0 || a >= g.dims.X() || b >= g.dims.Y() || c >= g.dims.Z()) continue;
        const std::size_t q = g.Index(a, b, c);
        if (now[q] && !seen[q]) seen[q] = 1, stack.push_back(q);
      }
    }
    births += !heldBefore;
  }
  return births;
}

// The far target ball is born under the linear blend; not here (X1's two balls part by a
// split in the shrink).
TEST(InflateShrink, NoPartIsBorn) {
  const Balls m;
  constexpr int kSteps = 40;
  ScalarField blend = m.f0;
  int bornUnderBlend = 0;
  std::vector<char> before = Inside(m.f0);
  for (int k = 1; k <= kSteps; ++k) {
    const double t = double(k) / kSteps;
    for (std::size_t n = 0; n < blend.values.size(); ++n) blend.values[n] = (1 - t) * m.f0.values[n] + t * m.f1.values[n];
    const std::vector<char> now = Inside(blend);
    bornUnderBlend += Births(m.g, before, now);
    before = now;
  }
  EXPECT_GE(bornUnderBlend, 1);  // the case is one the linear blend gets wrong
  const InflateShrink morph(m.f0, m.f1);
  ScalarField frame;
  int born = 0, mostParts = 0;
  before = Inside(m.f0);
  for (int k = 1; k <= kSteps; ++k) {
    morph.Frame(double(k) / kSteps, frame);
    const std::vector<char> now = Inside(frame);
    born += Births(m.g, before, now);
    mostParts = std::max(mostParts, Measure(frame).components);
    before = now;
  }
  EXPECT_EQ(born, 0);
  EXPECT_EQ(mostParts, 2);  // the split into X1's two balls
}

// A ball hollowed out into a cage, and into a cup: the withdrawal reaches the cage's inside
// through its six windows, the cup's through its mouth. Leaving first the nodes farthest from
// the target bears a cavity there (the cage's centre, the cup's floor), leaving last those
// deepest from the outside leaves a piece apart from the target (the cage's centre).
TEST(InflateShrink, HollowingACageOrACupBearsNoCavityAndLeavesNoPiece) {
  const eulermap::testing::CageScene cage;
  EXPECT_EQ(Measure(cage.f1).Handles(), 5);
  EXPECT_EQ(eulermap::testing::FramesNotOnePartWithoutCavities(InflateShrink(cage.f0, cage.f1), 40), std::vector<std::string>());
  const eulermap::testing::CupScene cup;
  EXPECT_EQ(eulermap::testing::FramesNotOnePartWithoutCavities(InflateShrink(cup.f0, cup.f1), 40), std::vector<std::string>());
}

} // namespace
