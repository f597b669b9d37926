// Topology of the inside set {f < 0} on the grid and its events (zero_set_topology.h), on
// analytic distance-like fields: the measured components, handles and cavities of known
// shapes; the simple-point test against the global measure; the events of linear blends
// between shapes of different topology, which must add up to the difference of the
// measures at every step.
#include "core/zero_set_topology.h"
#include "tests/support/fields.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>

using namespace eulermap;
using eulermap::testing::Sampled;

namespace {

using Shape = std::function<double(const Point3 &)>;

// nodes^3 nodes spread over [-half, half]^3.
Grid Cube(double half, int nodes) {
  Grid g;
  g.origin = Point3(-half, -half, -half);
  g.h = 2 * half / (nodes - 1);
  g.dims = vcg::Point3i(nodes, nodes, nodes);
  return g;
}

// Distance-like functions, negative inside.
Shape Sphere(const Point3 &c, double r) {
  return [=](const Point3 &p) { return vcg::Distance(p, c) - r; };
}
// Around the z axis through c: ring radius R, tube radius r.
Shape Torus(const Point3 &c, double R, double r) {
  return [=](const Point3 &p) {
    const Point3 d = p - c;
    return std::hypot(std::hypot(d[0], d[1]) - R, d[2]) - r;
  };
}
// Scaled so that it is the distance on the shortest axis (sign exact, distance-like).
Shape Ellipsoid(const Point3 &c, const Point3 &radii) {
  return [=](const Point3 &p) {
    const Point3 d = p - c;
    const double shortest = std::min(radii[0], std::min(radii[1], radii[2]));
    return (Point3(d[0] / radii[0], d[1] / radii[1], d[2] / radii[2]).Norm() - 1) * shortest;
  };
}
// Everything within `thickness` of the sphere of radius R.
Shape Shell(double R, double thickness) {
  return [=](const Point3 &p) { return std::abs(p.Norm() - R) - thickness; };
}
Shape Union(std::vector<Shape> shapes) {
  return [=](const Point3 &p) {
    double f = shapes.front()(p);
    for (const Shape &s : shapes) f = std::min(f, s(p));
    return f;
  };
}
// Tori along x, each ring tangent to the next: genus `count`.
Shape TorusChain(int count, double R, double r) {
  std::vector<Shape> tori;
  for (int n = 0; n < count; ++n) tori.push_back(Torus(Point3((2 * n - (count - 1)) * R, 0, 0), R, r));
  return Union(tori);
}

int Count(const std::vector<TopologyEvent> &events, TopologyEventKind kind) {
  return int(std::count_if(events.begin(), events.end(), [&](const TopologyEvent &e) { return e.kind == kind; }));
}

struct Figures {
  int components, handles, cavities, chi;
};
void ExpectFigures(const ZeroSetTopology &t, const Figures &want, const char *shape) {
  EXPECT_EQ(t.components, want.components) << shape;
  EXPECT_EQ(t.Handles(), want.handles) << shape;
  EXPECT_EQ(t.cavities, want.cavities) << shape;
  EXPECT_EQ(t.eulerCharacteristic, want.chi) << shape;
}

TEST(ZeroSetTopology, MeasuresAnalyticShapes) {
  const Grid g = Cube(2.0, 64);
  ExpectFigures(Measure(Sampled(g, Sphere(Point3(0, 0, 0), 1.2))), {1, 0, 0, 1}, "sphere");
  ExpectFigures(Measure(Sampled(g, Torus(Point3(0, 0, 0), 1.0, 0.35))), {1, 1, 0, 0}, "torus");
  ExpectFigures(Measure(Sampled(g, TorusChain(2, 0.8, 0.3))), {1, 2, 0, -1}, "two tori");
  ExpectFigures(Measure(Sampled(g, TorusChain(3, 0.55, 0.22))), {1, 3, 0, -2}, "three tori");
  ExpectFigures(Measure(Sampled(g, Shell(1.2, 0.2))), {1, 0, 1, 2}, "hollow sphere");
  ExpectFigures(Measure(Sampled(g, Union({Shell(1.4, 0.15), Sphere(Point3(0, 0, 0), 0.6)}))), {2, 0, 1, 3},
                "ball in a hollow sphere");
  ExpectFigures(Measure(Sampled(g, Union({Torus(Point3(0, 0, 0), 1.0, 0.3), Shell(1.8, 0.12)}))), {2, 1, 1, 2},
                "torus in a hollow sphere");

  const ZeroSetTopology two = Measure(Sampled(g, Union({Sphere(Point3(-0.9, 0, 0), 0.6), Sphere(Point3(0.9, 0.2, 0), 0.5)})));
  ExpectFigures(two, {2, 0, 0, 2}, "two spheres");
  ASSERT_EQ(two.parts.size(), 2u);
  // The parts in storage order (x fastest, z slowest): their centroids, sizes ~ volume / h^3.
  const double cell = g.h * g.h * g.h;
  for (const InsideComponent &part : two.parts) {
    const bool left = part.centroid[0] < 0;
    const Point3 centre = left ? Point3(-0.9, 0, 0) : Point3(0.9, 0.2, 0);
    const double r = left ? 0.6 : 0.5;
    EXPECT_LT(vcg::Distance(part.centroid, centre), 0.1 * g.h);
    EXPECT_NEAR(part.nodes * cell, 4.0 / 3 * M_PI * r * r * r, 0.03 * 4.0 / 3 * M_PI * r * r * r);
  }
  std::printf("two spheres: %zu and %zu nodes, centroids (%.4f %.4f %.4f) (%.4f %.4f %.4f)\n", two.parts[0].nodes,
              two.parts[1].nodes, two.parts[0].centroid[0], two.parts[0].centroid[1], two.parts[0].centroid[2],
              two.parts[1].centroid[0], two.parts[1].centroid[1], two.parts[1].centroid[2]);
}

// Digital cases on a 7^3 grid, X given node by node: the adjacency pair (6, 26) decides.
TEST(ZeroSetTopology, MeasuresDigitalCases) {
  const Grid g = Cube(3, 7);
  auto measure = [&](const std::vector<vcg::Point3i> &nodes) {
    ScalarField f(g, 1.0);
    for (const vcg::Point3i &c : nodes) f(c[0] + 3, c[1] + 3, c[2] + 3) = -1;
    return Measure(f);
  };
  ExpectFigures(measure({{0, 0, 0}}), {1, 0, 0, 1}, "one node");
  ExpectFigures(measure({{0, 0, 0}, {1, 1, 0}}), {2, 0, 0, 2}, "a diagonal pair: not 6-adjacent");
  ExpectFigures(measure({{0, 0, 0}, {1, 1, 1}}), {2, 0, 0, 2}, "a corner pair");
  std::vector<vcg::Point3i> ring, block;
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j) {
      if (i || j) ring.push_back({i, j, 0});
      for (int k = -1; k <= 1; ++k)
        if (i || j || k) block.push_back({i, j, k});
    }
  ExpectFigures(measure(ring), {1, 1, 0, 0}, "a ring of 8 nodes around a gap");
  ExpectFigures(measure(block), {1, 0, 1, 2}, "a 3x3x3 block without its centre");
  std::vector<vcg::Point3i> corners;  // the 4 nodes of a square's diagonal ring: 4 components
  for (const vcg::Point3i &c : ring)
    if ((c[0] == 0) != (c[1] == 0)) corners.push_back(c);
  ExpectFigures(measure(corners), {4, 0, 0, 4}, "4 nodes around a gap, diagonal to each other");
  // The complement is 26-connected: a diagonal chink in a closed box lets its inside out.
  std::vector<vcg::Point3i> box;
  for (int i = -2; i <= 2; ++i)
    for (int j = -2; j <= 2; ++j)
      for (int k = -2; k <= 2; ++k)
        if (std::max(std::abs(i), std::max(std::abs(j), std::abs(k))) == 2) box.push_back({i, j, k});
  ExpectFigures(measure(box), {1, 0, 1, 2}, "a closed box");
  box.erase(std::find(box.begin(), box.end(), vcg::Point3i(2, 2, 0)));
  ExpectFigures(measure(box), {1, 0, 0, 1}, "a closed box without one edge node: its inside out diagonally");
  // X on the grid's border: beyond the grid is outside.
  std::vector<vcg::Point3i> plane, border;
  for (int i = -3; i <= 3; ++i)
    for (int j = -3; j <= 3; ++j) {
      plane.push_back({i, j, 0});
      for (int k = -3; k <= 3; ++k)
        if (std::max(std::abs(i), std::max(std::abs(j), std::abs(k))) == 3) border.push_back({i, j, k});
    }
  ExpectFigures(measure(plane), {1, 0, 0, 1}, "a plane across the grid");
  ExpectFigures(measure(border), {1, 0, 1, 2}, "the grid's border layer");
}

// IsSimple against the global measure: a random neighbourhood in the middle of a 5^3 grid
// (X empty around it). A simple centre's flip leaves components, handles and cavities as
// they are, and Events reports nothing; any other flip is reported, and its events add up
// to the change Measure sees (which can be none: a handle gained and one lost at once).
TEST(ZeroSetTopology, SimplePointsAreTheFlipsThatChangeNothing) {
  const Grid g = Cube(2, 5);
  std::mt19937 random(12);
  int simple = 0, checked = 0, swapped = 0;
  for (double density : {0.2, 0.4, 0.5, 0.6, 0.8})
    for (int trial = 0; trial < 4000; ++trial) {
      std::bernoulli_distribution in(density);
      ScalarField without(g, 1.0);
      std::uint32_t neighbourhood = 0;
      for (int p = 0; p < 27; ++p)
        if (p != 13 && in(random)) {
          neighbourhood |= 1u << p;
          without(1 + p % 3, 1 + p / 3 % 3, 1 + p / 9) = -1;
        }
      ScalarField with = without;
      with(2, 2, 2) = -1;
      const ZeroSetTopology before = Measure(without), after = Measure(with);
      const TopologyChange change = Difference(before, after);
      const std::vector<TopologyEvent> joining = Events(without, with, 0), leaving = Events(with, without, 0);
      ASSERT_EQ(Effect(joining), change) << "neighbourhood " << neighbourhood;
      ASSERT_EQ(Effect(leaving), Difference(after, before)) << "neighbourhood " << neighbourhood;
      ASSERT_EQ(IsSimple(neighbourhood), joining.empty()) << "neighbourhood " << neighbourhood;
      ASSERT_EQ(IsSimple(neighbourhood), leaving.empty()) << "neighbourhood " << neighbourhood;
      if (IsSimple(neighbourhood)) {
        ASSERT_EQ(change, TopologyChange()) << "neighbourhood " << neighbourhood;
        ASSERT_EQ(before.eulerCharacteristic, after.eulerCharacteristic) << "neighbourhood " << neighbourhood;
      } else if (change == TopologyChange()) {
        ++swapped;
        ASSERT_EQ(Count(joining, TopologyEventKind::HandleGained), Count(joining, TopologyEventKind::HandleLost));
        ASSERT_GE(Count(joining, TopologyEventKind::HandleGained), 1);
      }
      simple += IsSimple(neighbourhood);
      ++checked;
    }
  std::printf("%d of %d random neighbourhoods simple; %d others leave the Betti numbers as they were "
              "(a handle gained and one lost)\n", simple, checked, swapped);
  EXPECT_GT(simple, checked / 10);
  EXPECT_LT(simple, checked * 9 / 10);
}

// Random smooth fields (sums of bumps around a level: mostly outside, or mostly inside with
// bubbles), with many components, handles and cavities: over a blend of two of them, the
// tracker's figures equal Measure at every step, the events add up to the difference, and
// every kind of event occurs.
TEST(ZeroSetTopology, EventsAddUpOnRandomFields) {
  const Grid g = Cube(1, 24);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-1.2, 1.2), weight(-1, 1);
  auto bumps = [&](double level) {
    std::vector<std::pair<Point3, double>> b;
    for (int n = 0; n < 60; ++n) b.push_back({Point3(coordinate(random), coordinate(random), coordinate(random)), weight(random)});
    return Sampled(g, [b, level](const Point3 &p) {
      double f = level;
      for (const auto &[c, w] : b) f += w * std::exp(-vcg::SquaredDistance(p, c) / 0.04);
      return f;
    });
  };
  std::vector<int> kinds(9, 0);
  for (int pair = 0; pair < 8; ++pair) {
    const double level = pair % 2 ? -0.25 : 0.05;
    const ScalarField f0 = bumps(level), f1 = bumps(level);
    InsideSetTracker tracker(f0);
    ZeroSetTopology before = Measure(f0);
    int events = 0;
    const int steps = 10;
    for (int k = 0; k < steps; ++k) {
      ScalarField f(g, 0.0);
      const double t = double(k + 1) / steps;
      for (std::size_t n = 0; n < f.values.size(); ++n) f.values[n] = (1 - t) * f0.values[n] + t * f1.values[n];
      const std::vector<TopologyEvent> e = tracker.Advance(f, k);
      const ZeroSetTopology after = Measure(f), followed = tracker.Topology();
      ASSERT_EQ(Effect(e), Difference(before, after)) << "pair " << pair << " step " << k;
      ASSERT_EQ(followed.components, after.components);
      ASSERT_EQ(followed.cavities, after.cavities);
      ASSERT_EQ(followed.eulerCharacteristic, after.eulerCharacteristic);
      for (const TopologyEvent &event : e) ++kinds[int(event.kind)];
      events += int(e.size());
      before = after;
    }
    std::printf("random pair %d: %d events over %d steps, end: %d components, %d handles, %d cavities\n", pair, events,
                steps, before.components, before.Handles(), before.cavities);
  }
  for (int kind = 0; kind < 9; ++kind) {
    std::printf("  %s: %d\n", Name(TopologyEventKind(kind)), kinds[kind]);
    EXPECT_GT(kinds[kind], 0) << Name(TopologyEventKind(kind));
  }
}

// The linear blend f(t) = (1 - t) f0 + t f1 over `steps` steps: every step's events (from
// Events on its two frames) add up to the difference of Measure between them, and the
// tracker followed over all steps finds the same events. Returns all events.
std::vector<TopologyEvent> BlendEvents(const ScalarField &f0, const ScalarField &f1, int steps, const char *pair) {
  auto frame = [&](int k) {
    ScalarField f(f0.grid, 0.0);
    const double t = double(k) / steps;
    for (std::size_t n = 0; n < f.values.size(); ++n) f.values[n] = (1 - t) * f0.values[n] + t * f1.values[n];
    return f;
  };
  std::vector<TopologyEvent> all;
  InsideSetTracker tracker(f0);
  ScalarField before = frame(0);
  for (int k = 0; k < steps; ++k) {
    const ScalarField after = frame(k + 1);
    const std::vector<TopologyEvent> events = Events(before, after, k), followed = tracker.Advance(after, k);
    EXPECT_EQ(Effect(events), Difference(Measure(before), Measure(after))) << pair << ", step " << k;
    EXPECT_EQ(events.size(), followed.size()) << pair << ", step " << k;
    for (std::size_t n = 0; n < std::min(events.size(), followed.size()); ++n) {
      EXPECT_EQ(events[n].kind, followed[n].kind) << pair << ", step " << k;
      EXPECT_EQ(events[n].node, followed[n].node) << pair << ", step " << k;
    }
    for (const TopologyEvent &e : events)
      std::printf("  %s: step %d (+%.3f) %s at node (%d %d %d), (%.3f %.3f %.3f)\n", pair, e.step, e.crossing,
                  Name(e.kind), e.node[0], e.node[1], e.node[2], e.position[0], e.position[1], e.position[2]);
    all.insert(all.end(), events.begin(), events.end());
    before = after;
  }
  return all;
}

TEST(ZeroSetTopology, SphereToTorusGainsAHandleOnTheHoleAxis) {
  const Grid g = Cube(1.6, 48);
  const Shape torus = Torus(Point3(0, 0, 0), 0.9, 0.35);
  const std::vector<TopologyEvent> events =
      BlendEvents(Sampled(g, Sphere(Point3(0, 0, 0), 1.25)), Sampled(g, torus), 20, "sphere -> torus");
  const TopologyChange net = Effect(events);
  EXPECT_EQ(net, (TopologyChange{0, 1, 0}));
  int handles = 0;
  for (const TopologyEvent &e : events)
    if (e.kind == TopologyEventKind::HandleGained || e.kind == TopologyEventKind::HandleLost) {
      ++handles;
      // An even node count: no node on the axis, the nearest four h / sqrt(2) from it.
      EXPECT_LT(std::hypot(e.position[0], e.position[1]), g.h) << "a handle event off the torus's axis";
    }
  EXPECT_GE(handles, 1);
}

TEST(ZeroSetTopology, TwoSpheresMergeIntoOneBlob) {
  const Grid g = Cube(1.6, 48);
  const std::vector<TopologyEvent> events =
      BlendEvents(Sampled(g, Union({Sphere(Point3(-0.8, 0, 0), 0.45), Sphere(Point3(0.8, 0, 0), 0.45)})),
                  Sampled(g, Ellipsoid(Point3(0, 0, 0), Point3(1.35, 0.6, 0.6))), 20, "two spheres -> blob");
  EXPECT_EQ(Effect(events), (TopologyChange{-1, 0, 0}));
  EXPECT_GE(Count(events, TopologyEventKind::PartsMerged), 1);
  for (const TopologyEvent &e : events) EXPECT_LT(std::abs(e.position[0]), g.h) << "off the plane between the spheres";
}

TEST(ZeroSetTopology, SphereSplitsIntoTwo) {
  const Grid g = Cube(1.6, 48);
  const std::vector<TopologyEvent> events =
      BlendEvents(Sampled(g, Ellipsoid(Point3(0, 0, 0), Point3(1.35, 0.6, 0.6))),
                  Sampled(g, Union({Sphere(Point3(-0.8, 0, 0), 0.45), Sphere(Point3(0.8, 0, 0), 0.45)})), 20,
                  "blob -> two spheres");
  EXPECT_EQ(Effect(events), (TopologyChange{1, 0, 0}));
  EXPECT_GE(Count(events, TopologyEventKind::PartSplit), 1);
  for (const TopologyEvent &e : events) EXPECT_LT(std::abs(e.position[0]), g.h) << "off the plane between the spheres";
}

TEST(ZeroSetTopology, SphereToThreeToriGainsThreeHandles) {
  const Grid g = Cube(2.0, 64);
  const std::vector<TopologyEvent> events = BlendEvents(Sampled(g, Ellipsoid(Point3(0, 0, 0), Point3(1.8, 0.8, 0.5))),
                                                        Sampled(g, TorusChain(3, 0.55, 0.22)), 20, "sphere -> 3 tori");
  EXPECT_EQ(Effect(events), (TopologyChange{0, 3, 0}));
  EXPECT_GE(Count(events, TopologyEventKind::HandleGained), 3);
  for (const TopologyEvent &e : events) {  // each on the axis of one torus (x = -1.1, 0, 1.1)
    const double x = e.position[0], offAxis = std::min({std::abs(x + 1.1), std::abs(x), std::abs(x - 1.1)});
    EXPECT_LT(std::hypot(offAxis, e.position[1]), g.h) << Name(e.kind) << " off the tori's axes";
  }
}

// Each event names the piece of its step's sign flips (TopologyEvent::sweep): a front that
// fills the gap under a table's top from the bottom up within one step closes a window
// (handles gained at the bottom, digital pairs there) and fills it (the last handle lost, in
// the window's middle), all in one piece, while a ball born apart in the same step is another.
TEST(ZeroSetTopology, EventsNameThePieceOfTheirStepsFlips) {
  const Grid g = Cube(1.0, 41);
  auto box = [](const Point3 &lo, const Point3 &hi) {
    return [lo, hi](const Point3 &p) {
      double d = -1e9;
      for (int a = 0; a < 3; ++a) d = std::max({d, lo[a] - p[a], p[a] - hi[a]});
      return d;  // a distance-like field: negative inside
    };
  };
  const Shape table = Union({box(Point3(-0.6, -0.2, -0.6), Point3(-0.4, 0.2, 0.6)),
                             box(Point3(0.4, -0.2, -0.6), Point3(0.6, 0.2, 0.6)),
                             box(Point3(-0.6, -0.2, 0.4), Point3(0.6, 0.2, 0.6))});
  const Shape block = box(Point3(-0.6, -0.2, -0.6), Point3(0.6, 0.2, 0.6));
  // The block, deepest at the bottom: the gap's nodes cross 0 earliest there.
  const Shape filled = [block](const Point3 &p) {
    const double d = block(p);
    return d < 0 ? d - 0.5 * (0.6 - p[2]) : d;
  };
  const std::vector<TopologyEvent> events =
      Events(Sampled(g, table), Sampled(g, Union({filled, Sphere(Point3(0, 0.7, -0.7), 0.15)})), 0);
  EXPECT_EQ(Effect(events), (TopologyChange{1, 0, 0}));
  const TopologyEvent *gained = nullptr, *lost = nullptr, *born = nullptr;
  for (const TopologyEvent &e : events) {  // the last of each kind
    if (e.kind == TopologyEventKind::HandleGained) gained = &e;
    if (e.kind == TopologyEventKind::HandleLost) lost = &e;
    if (e.kind == TopologyEventKind::ComponentBorn) born = &e;
  }
  ASSERT_TRUE(gained && lost && born);
  EXPECT_EQ(gained->sweep, lost->sweep);
  EXPECT_NE(born->sweep, gained->sweep);
  EXPECT_GT(lost->position[2] - gained->position[2], 0.3);  // the window closes at the bottom, fills at the top
}

TEST(ZeroSetTopology, Timings) {
  using Clock = std::chrono::steady_clock;
  auto seconds = [](Clock::time_point since) { return std::chrono::duration<double>(Clock::now() - since).count(); };
  for (int nodes : {64, 128}) {
    const Grid g = Cube(1.6, nodes);
    const ScalarField sphere = Sampled(g, Sphere(Point3(0, 0, 0), 1.25)), torus = Sampled(g, Torus(Point3(0, 0, 0), 0.9, 0.35));
    auto t0 = Clock::now();
    const ZeroSetTopology m = Measure(torus);
    const double measure = seconds(t0);
    EXPECT_EQ(m.Handles(), 1);
    // The 20 steps from sphere to torus: Events on each step's two frames (the slowest
    // step), and InsideSetTracker over all of them.
    auto frame = [&](int k) {
      ScalarField f(g, 0.0);
      for (std::size_t n = 0; n < f.values.size(); ++n) f.values[n] = (1 - k / 20.0) * sphere.values[n] + k / 20.0 * torus.values[n];
      return f;
    };
    double events = 0, advance = 0, advances = 0;
    int mostFlips = 0;
    t0 = Clock::now();
    InsideSetTracker tracker(frame(0));
    const double start = seconds(t0);
    ScalarField before = frame(0);
    for (int k = 0; k < 20; ++k) {
      const ScalarField after = frame(k + 1);
      t0 = Clock::now();
      Events(before, after, k);
      events = std::max(events, seconds(t0));
      t0 = Clock::now();
      tracker.Advance(after, k);
      advance = std::max(advance, seconds(t0));
      advances += seconds(t0);
      int flips = 0;
      for (std::size_t n = 0; n < g.NodeCount(); ++n) flips += (before.values[n] < 0) != (after.values[n] < 0);
      mostFlips = std::max(mostFlips, flips);
      before = after;
    }
    std::printf("%d^3 nodes: Measure %.3f s; Events, slowest of 20 steps (up to %d flips a step) %.3f s; "
                "InsideSetTracker: start %.3f s, Advance slowest %.4f s, all 20 %.3f s\n",
                nodes, measure, mostFlips, events, start, advance, advances);
  }
}

} // namespace
