// The topology of the inside set along a whole morph (morph_topology.h), on the linear blend
// of analytic fields: the first frame is f(., 0)'s topology and the last f(., 1)'s; the
// events add up to the difference; a frame is kept only where the topology changed; the
// progress callback sees every step in order, and one that throws ends the tracking.
#include "core/morph.h"
#include "core/morph_topology.h"

#include "tests/support/fields.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

using namespace eulermap;
using eulermap::testing::Sampled;

namespace {

// A sphere becoming a torus on 32^3 nodes over [-1.6, 1.6]^3.
struct SphereToTorus {
  Grid g = [] {
    Grid g;
    g.origin = Point3(-1.6, -1.6, -1.6);
    g.h = 3.2 / 31;
    g.dims = vcg::Point3i(32, 32, 32);
    return g;
  }();
  ScalarField f0 = Sampled(g, [](const Point3 &p) { return p.Norm() - 1.25; });
  ScalarField f1 = Sampled(g, [](const Point3 &p) { return std::hypot(std::hypot(p[0], p[1]) - 0.9, p[2]) - 0.35; });
  Morph morph{f0, f1, {}, {}};
};

const int kSteps = 16;

TopologyFrame FrameOf(const ZeroSetTopology &t) { return TopologyFrame{0, t.components, t.Handles(), t.cavities}; }

void ExpectSameTopology(const TopologyFrame &a, const TopologyFrame &b) {
  EXPECT_EQ(a.components, b.components);
  EXPECT_EQ(a.handles, b.handles);
  EXPECT_EQ(a.cavities, b.cavities);
}

TEST(MorphTopology, TheFramesStartAtTheSourceAndEndAtTheTarget) {
  const SphereToTorus s;
  const TopologyHistory h = TrackTopology(s.morph, kSteps);
  ASSERT_GE(h.frames.size(), 2u);
  EXPECT_EQ(h.frames.front().step, -1);
  ExpectSameTopology(h.frames.front(), FrameOf(Measure(s.f0)));
  ExpectSameTopology(h.frames.back(), FrameOf(Measure(s.f1)));
  EXPECT_EQ(h.frames.back().handles, 1);
}

TEST(MorphTopology, TheEventsAddUpToTheChange) {
  const SphereToTorus s;
  const TopologyHistory h = TrackTopology(s.morph, kSteps);
  EXPECT_EQ(Effect(h.events), Difference(Measure(s.f0), Measure(s.f1)));
  for (std::size_t n = 0; n < h.events.size(); ++n) {
    EXPECT_GE(h.events[n].step, 0);
    EXPECT_LT(h.events[n].step, kSteps);
    if (n) EXPECT_GE(h.events[n].step, h.events[n - 1].step) << "in step order";
  }
}

TEST(MorphTopology, AFrameIsKeptOnlyWhereTheTopologyChanged) {
  const SphereToTorus s;
  const TopologyHistory h = TrackTopology(s.morph, kSteps);
  for (std::size_t n = 1; n < h.frames.size(); ++n) {
    const TopologyFrame &a = h.frames[n - 1], &b = h.frames[n];
    EXPECT_GT(b.step, a.step);
    EXPECT_TRUE(a.components != b.components || a.handles != b.handles || a.cavities != b.cavities) << b.step;
  }
}

// Each step is heard before its frame and before its sign flips (and before its topology
// where the step has events), with the share done; the first frame's labelling (a pass or
// two over the grid) is heard while it runs, at share 0.
TEST(MorphTopology, ProgressSeesEveryStepInOrder) {
  const SphereToTorus s;
  std::vector<double> shares;
  TrackTopology(s.morph, kSteps, [&](double share) { shares.push_back(share); });
  for (std::size_t n = 1; n < shares.size(); ++n) EXPECT_GE(shares[n], shares[n - 1]);
  for (int k = 0; k < kSteps; ++k)
    EXPECT_EQ(std::count(shares.begin(), shares.end(), double(k) / kSteps) >= 2, true) << "step " << k;
  EXPECT_LE(std::count_if(shares.begin(), shares.end(), [](double share) { return share > 0; }), 3 * (kSteps - 1));
  EXPECT_GE(std::count(shares.begin(), shares.end(), 0.0), 3) << "the labelling of the first frame is heard";
}

TEST(MorphTopology, AProgressThatThrowsEndsTheTracking) {
  const SphereToTorus s;
  int late = 0;  // calls from share 0.25 on: the first one ends it
  EXPECT_THROW(TrackTopology(s.morph, kSteps,
                             [&](double share) {
                               if (share < 0.25) return;
                               ++late;
                               throw std::runtime_error("cancelled");
                             }),
               std::runtime_error);
  EXPECT_EQ(late, 1);
}

// The first call comes while the first frame is made (inside the morph's Interrupt): a throw
// there ends the tracking at once, and reaches the caller as thrown.
TEST(MorphTopology, AProgressThatThrowsWhileTheFirstFrameIsMadeEndsTheTracking) {
  const SphereToTorus s;
  int calls = 0;
  EXPECT_THROW(TrackTopology(s.morph, kSteps,
                             [&](double) {
                               ++calls;
                               throw std::runtime_error("cancelled");
                             }),
               std::runtime_error);
  EXPECT_EQ(calls, 1);
}

} // namespace
