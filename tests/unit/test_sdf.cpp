// Unit tests of core/sdf.h: winding numbers and the signed distance fields f0, f1, checked
// against analytic shapes and the shared meshes (closest points: test_closest).
#include "core/closest.h"
#include "core/sdf.h"
#include "tests/support/fields.h"
#include "tests/support/meshes.h"

#include <gtest/gtest.h>
#include <omp.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg/space/distance3.h>
#include <vcg/space/segment3.h>
#include <vcg/space/triangle3.h>
#include <vcg/simplex/face/distance.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <queue>
#include <random>
#include <vector>

namespace eulermap {
namespace {

using testing::BoxSignedDistance;
using testing::DataMesh;
using testing::LoadMesh;
using testing::MakeBox;
using testing::MakeSphere;

double Seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

// Brute-force winding number: the exact sum of all triangles' solid angles, here by
// the half-angle formula of Van Oosterom & Strackee written out independently of sdf.cpp.
double BruteWinding(const Mesh &m, const Point3 &p) {
  double sum = 0;
  for (const Face &f : m.face) {
    if (f.IsD()) continue;
    const Point3 a = f.cP(0) - p, b = f.cP(1) - p, c = f.cP(2) - p;
    const double num = a * (b ^ c);
    const double den = a.Norm() * b.Norm() * c.Norm() + (a * b) * c.Norm() + (b * c) * a.Norm() + (c * a) * b.Norm();
    sum += 2 * std::atan2(num, den);
  }
  return sum / (4 * M_PI);
}

// Winding numbers at every node of the grid (parallel).
std::vector<double> WindingAtNodes(const WindingNumber &w, const Grid &g) {
  std::vector<double> out(g.NodeCount());
  const long n = long(g.NodeCount());
#pragma omp parallel for schedule(dynamic, 256)
  for (long idx = 0; idx < n; ++idx) {
    const int i = int(idx % g.dims.X()), j = int((idx / g.dims.X()) % g.dims.Y()), k = int(idx / (long(g.dims.X()) * g.dims.Y()));
    out[idx] = w(g.Node(i, j, k));
  }
  return out;
}

// ---------------------------------------------------------------- WindingNumber

TEST(WindingNumber, SphereIsOneInsideZeroOutside) {
  Mesh m;
  MakeSphere(m, Point3(0.1, -0.2, 0.3), 1, 3);
  const WindingNumber w(m);
  // The exact sum is an integer for a closed mesh; the tree's far-field expansion is
  // within ~1e-3 of it (sdf.cpp).
  for (const Point3 &p : {Point3(0.1, -0.2, 0.3), Point3(0.5, 0.1, 0.4), Point3(0.1, 0.7, 0.3)}) {
    EXPECT_NEAR(BruteWinding(m, p), 1, 1e-12);
    EXPECT_NEAR(w(p), 1, 1e-3);
  }
  for (const Point3 &p : {Point3(3, 0, 0), Point3(0.1, -0.2, 1.4), Point3(-20, 5, 1)}) {
    EXPECT_NEAR(BruteWinding(m, p), 0, 1e-12);
    EXPECT_NEAR(w(p), 0, 1e-3);
  }
}

TEST(WindingNumber, HierarchicalMatchesBruteForceOnBunny) {
  Mesh m;
  LoadMesh(DataMesh("bunny.off"), m);
  const WindingNumber w(m);
  std::mt19937 rng(11);
  const Box3 b = m.bbox;
  std::uniform_real_distribution<double> u(-0.25, 1.25);
  std::vector<Point3> pts;
  for (int i = 0; i < 400; ++i)  // in and around the box
    pts.push_back(Point3(b.min.X() + u(rng) * b.DimX(), b.min.Y() + u(rng) * b.DimY(), b.min.Z() + u(rng) * b.DimZ()));
  std::uniform_int_distribution<int> uv(0, m.vn - 1);
  std::uniform_real_distribution<double> off(-0.01, 0.01);
  for (int i = 0; i < 200; ++i) {  // close to the surface, on both sides
    const Vertex &v = m.vert[uv(rng)];
    pts.push_back(v.cP() + v.cN() * (off(rng) * b.Diag()));
  }
  double maxErr = 0;
  for (const Point3 &p : pts) maxErr = std::max(maxErr, std::abs(w(p) - BruteWinding(m, p)));
  std::printf("[ figures  ] bunny: hierarchical vs exact winding number, max |error| over %zu points = %.2e\n", pts.size(), maxErr);
  EXPECT_LT(maxErr, 1e-3);
}

// ---------------------------------------------------------------- SignedDistance

TEST(SignedDistance, SphereMatchesAnalyticWithinFacetingError) {
  const Point3 c(0.1, -0.2, 0.3);
  const double r = 1;
  for (int subdiv : {4, 5}) {
    Mesh m;
    MakeSphere(m, c, r, subdiv);
    // The faceted sphere lies in the shell r - eps <= |x - c| <= r, eps = r minus the
    // smallest distance from c to a face's plane (its vertices lie on the sphere). Then
    // for a node outside the shell, | |p-c| - r - f(p) | <= eps (the radial ray crosses the
    // facets inside the shell), and at most 2 eps inside it. That holds for the exact
    // distance, which the propagation gives within one cell of the surface; farther away it
    // may take a face up to a third of a cell farther than the nearest (distance_transform.h;
    // the centre of a sphere, where all faces are nearly as near, is the worst case: 0.30 cells).
    double eps = 0;
    for (const Face &f : m.face) {
      const Point3 n = ((f.cP(1) - f.cP(0)) ^ (f.cP(2) - f.cP(0))).Normalize();
      eps = std::max(eps, r - std::abs((c - f.cP(0)) * n));
    }
    const Grid g = Grid::Enclosing(m.bbox, 48);
    const ScalarField f = SignedDistance(m, g);
    double maxErr = 0;
    int wrongSign = 0, checkedSign = 0;
    g.ForEachNode([&](int i, int j, int k, std::size_t idx) {
      const Point3 p = g.Node(i, j, k);
      const double truth = (p - c).Norm() - r;
      const double err = std::abs(f.values[idx] - truth);
      maxErr = std::max(maxErr, err);
      const double bound = (truth > 0 || truth < -eps ? eps : 2 * eps) + (std::abs(truth) > g.h ? 0.35 * g.h : 0);
      EXPECT_LE(err, bound + 1e-12) << "node " << i << " " << j << " " << k;
      if (std::abs(truth) > g.h) {
        ++checkedSign;
        if ((f.values[idx] < 0) != (truth < 0)) ++wrongSign;
      }
    });
    std::printf("[ figures  ] sphere r=1, subdivisions %d (%d faces), h=%.4f: faceting bound eps=%.2e, max |f - (|p-c|-r)| = %.2e\n",
                subdiv, m.fn, g.h, eps, maxErr);
    EXPECT_EQ(wrongSign, 0);
    EXPECT_GT(checkedSign, int(g.NodeCount() * 0.9));
  }
}

TEST(SignedDistance, BoxMatchesAnalyticExactly) {
  Mesh m;
  const Box3 box(Point3(-0.5, -0.3, -0.4), Point3(0.6, 0.5, 0.45));
  MakeBox(m, box, 4);
  const Grid g = Grid::Enclosing(box, 40);
  const ScalarField f = SignedDistance(m, g);
  double maxErr = 0;
  int wrongSign = 0;
  g.ForEachNode([&](int i, int j, int k, std::size_t idx) {
    const double truth = BoxSignedDistance(box, g.Node(i, j, k));
    maxErr = std::max(maxErr, std::abs(f.values[idx] - truth));
    if (std::abs(truth) > 1e-3 * g.h && (f.values[idx] < 0) != (truth < 0)) ++wrongSign;
  });
  std::printf("[ figures  ] box (%d faces), h=%.4f: max |f - sdf| = %.2e = %.2e cells\n", m.fn, g.h, maxErr, maxErr / g.h);
  EXPECT_LT(maxErr, 1e-6 * g.h);
  EXPECT_EQ(wrongSign, 0);
}

// The boundary edges of a mesh (updates FF adjacency).
std::vector<vcg::Segment3d> BorderEdges(Mesh &m) {
  vcg::tri::UpdateTopology<Mesh>::FaceFace(m);
  std::vector<vcg::Segment3d> border;
  for (Face &f : m.face)
    for (int e = 0; e < 3; ++e)
      if (vcg::face::IsBorder(f, e)) border.emplace_back(f.P0(e), f.P1(e));
  return border;
}

// Volume enclosed by a mesh with holes capped by fans from the length-weighted centroid
// of its boundary (divergence theorem about that point: the fans contribute nothing).
// Meant for one hole, as camelhead's.
double CappedVolume(Mesh &m) {
  Point3 o(0, 0, 0);
  double len = 0;
  for (const auto &s : BorderEdges(m)) {
    o += s.MidPoint() * s.Length();
    len += s.Length();
  }
  if (len > 0) o /= len;
  double v = 0;
  for (const Face &f : m.face) v += (f.cP(0) - o) * ((f.cP(1) - o) ^ (f.cP(2) - o)) / 6;
  return v;
}

// camelhead.off, an open mesh (its neck is a hole), at 64 cells: f, the accurate winding
// number at every node, computed once for the tests below.
class CamelheadField : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    LoadMesh(DataMesh("camelhead.off"), m);
    g = Grid::Enclosing(m.bbox, 64);
    const auto t0 = std::chrono::steady_clock::now();
    f = SignedDistance(m, g);
    seconds = Seconds(t0);
    w = WindingAtNodes(WindingNumber(m), g);
  }
  static Mesh m;
  static Grid g;
  static ScalarField f;
  static double seconds;
  static std::vector<double> w;
};
Mesh CamelheadField::m;
Grid CamelheadField::g;
ScalarField CamelheadField::f;
double CamelheadField::seconds = 0;
std::vector<double> CamelheadField::w;

// The negative nodes form one 6-connected component away from the grid's border.
TEST_F(CamelheadField, InsideIsOneComponentAwayFromTheBorder) {
  std::vector<char> seen(g.NodeCount(), 0);
  int components = 0;
  bool touchesBorder = false;
  g.ForEachNode([&](int i, int j, int k, std::size_t idx) {
    if (f.values[idx] >= 0) return;
    if (seen[idx]) return;
    ++components;
    std::queue<vcg::Point3i> q;
    q.push(vcg::Point3i(i, j, k));
    seen[idx] = 1;
    while (!q.empty()) {
      const vcg::Point3i n = q.front();
      q.pop();
      for (int a = 0; a < 3; ++a)
        if (n[a] == 0 || n[a] == g.dims[a] - 1) touchesBorder = true;
      for (int a = 0; a < 3; ++a)
        for (int s : {-1, 1}) {
          vcg::Point3i nb = n;
          nb[a] += s;
          if (nb[a] < 0 || nb[a] >= g.dims[a]) continue;
          const std::size_t id = g.Index(nb[0], nb[1], nb[2]);
          if (f.values[id] < 0 && !seen[id]) {
            seen[id] = 1;
            q.push(nb);
          }
        }
    }
  });
  EXPECT_EQ(components, 1);
  EXPECT_FALSE(touchesBorder);
}

// The sign is the accurate winding number's (SignedDistance decides most nodes with a
// cheaper evaluation, WindingNumber::Inside).
TEST_F(CamelheadField, SignIsTheWindingNumbers) {
  int signMismatches = 0;
  for (std::size_t i = 0; i < w.size(); ++i)
    if (f.values[i] != 0 && (f.values[i] < 0) != (w[i] >= 0.5)) ++signMismatches;
  EXPECT_EQ(signMismatches, 0);
}

// Far outside (more than 2 cells from the surface) the winding number is small, except in
// front of the open neck: w is harmonic and continuous across the hole, so near the
// opening it takes every value between 0 and 1/2 (measured: all nodes with
// w >= 0.2 lie within 10 cells of the rim, whose radius is ~14 cells). Away from the
// hole (farther from the rim than its radius) w < 0.2 must hold; over all far nodes
// the share is lower (measured 98.3%).
TEST_F(CamelheadField, FarOutsideTheWindingNumberIsSmall) {
  const std::vector<vcg::Segment3d> rim = BorderEdges(m);
  ASSERT_FALSE(rim.empty());
  Box3 rimBox;
  for (const auto &s : rim) rimBox.Add(s.P0());
  const double rimRadius = rimBox.Diag() / 2;
  int far = 0, farSmall = 0, awayFromHole = 0, awayFromHoleSmall = 0;
  g.ForEachNode([&](int i, int j, int k, std::size_t idx) {
    if (f.values[idx] <= 2 * g.h) return;
    ++far;
    farSmall += w[idx] < 0.2;
    double toRim = 1e300;
    for (const auto &s : rim) {
      Point3 c;
      double d;
      vcg::SegmentPointDistance(s, g.Node(i, j, k), c, d);
      toRim = std::min(toRim, d);
    }
    if (toRim > rimRadius) {
      ++awayFromHole;
      awayFromHoleSmall += w[idx] < 0.2;
    }
  });
  std::printf("[ figures  ] camelhead: far outside (> 2 cells) with w < 0.2: %d/%d = %.2f%%; away from the hole (> %.1f cells from the rim): %d/%d\n",
              farSmall, far, 100.0 * farSmall / far, rimRadius / g.h, awayFromHoleSmall, awayFromHole);
  EXPECT_GE(awayFromHoleSmall, 0.99 * awayFromHole);
  EXPECT_GE(farSmall, 0.95 * far);
}

// The negative volume agrees with the volume of the mesh capped at its hole. Node
// counting misclassifies only nodes within a cell of the surface, and those errors
// largely cancel on a smooth surface; the flat cap and the w = 1/2 surface across the
// neck differ by a sliver. Measured: 0.5%. We accept 3%, which still catches a lost
// part (a wrong sign over the neck or an ear moves it by more).
TEST_F(CamelheadField, NegativeVolumeIsTheCappedMeshVolume) {
  int negatives = 0;
  for (double v : f.values) negatives += v < 0;
  const double vNeg = negatives * g.h * g.h * g.h;
  const double vMesh = CappedVolume(m);
  const Box3 gb = g.Bounds();
  const double vGrid = gb.DimX() * gb.DimY() * gb.DimZ();
  std::printf("[ figures  ] camelhead (%d faces): grid %dx%dx%d, h=%.4g, SDF %.2f s; negative nodes %d = %.2f%% of the grid; "
              "negative volume %.5g vs capped mesh volume %.5g (diff %+.2f%%)\n",
              m.fn, g.dims.X(), g.dims.Y(), g.dims.Z(), g.h, seconds, negatives, 100.0 * negatives / g.NodeCount(), vNeg, vMesh,
              100 * (vNeg - vMesh) / vMesh);
  EXPECT_GT(vMesh, 0);
  EXPECT_LE(std::abs(vNeg - vMesh), 0.03 * vMesh);
  EXPECT_GT(vNeg, 0.05 * vGrid);  // the inside is not a sliver of the grid
  EXPECT_LT(vNeg, 0.5 * vGrid);   // nor most of it
}

// A point deep inside — the centroid of the inside nodes (w > 1/2) farthest from the
// surface — has a negative value, and a winding number near 1.
TEST_F(CamelheadField, ADeepPointIsInside) {
  double deepest = 0;
  for (std::size_t i = 0; i < w.size(); ++i)
    if (w[i] > 0.5) deepest = std::max(deepest, std::abs(f.values[i]));
  Point3 centroid(0, 0, 0);
  int count = 0;
  g.ForEachNode([&](int i, int j, int k, std::size_t idx) {
    if (w[idx] > 0.5 && std::abs(f.values[idx]) >= 0.8 * deepest) {
      centroid += g.Node(i, j, k);
      ++count;
    }
  });
  ASSERT_GT(count, 0);
  centroid /= count;
  EXPECT_GT(deepest, 2 * g.h);
  EXPECT_LT(f.Value(centroid), 0);
  EXPECT_GT(WindingNumber(m)(centroid), 0.9);
}

// The propagated distance (distance_transform.h) against a search per node (closest.h):
// exact within one cell of the surface (seeded), never below the truth, and off by a small
// part of a cell where it is off at all (near the medial axis). The sign flooded from the
// nodes next to a closed surface against the winding number at every node.
TEST(SignedDistance, PropagatedDistanceMatchesSearch) {
  for (const char *name : {"bunny.off", "camelhead.off", "decimated-knight.off"}) {
    Mesh m;
    LoadMesh(DataMesh(name), m);
    const Grid g = Grid::Enclosing(m.bbox, 64);
    const auto t0 = std::chrono::steady_clock::now();
    const ScalarField f = SignedDistance(m, g);
    const double seconds = Seconds(t0);
    const ClosestPoint closest(m);
    const WindingNumber winding(m);
    std::vector<double> errors;
    int below = 0, nearOff = 0, wrongSign = 0;
    g.ForEachNode([&](int i, int j, int k, std::size_t idx) {
      const Point3 p = g.Node(i, j, k);
      double truth = closest.Query(p).distance;
      const double got = std::abs(f.values[idx]);
      if (got < truth - 1e-12) {  // vcglib's point-triangle test (the search's) errs by up to ~1e-3 cells: brute force
        truth = std::numeric_limits<double>::max();
        for (const Face &t : m.face) {
          double dist;
          Point3 q;
          vcg::TrianglePointDistance(vcg::Triangle3<double>(t.cP(0), t.cP(1), t.cP(2)), p, dist, q);
          truth = std::min(truth, dist);
        }
        below += got < truth - 1e-12;
      }
      if (truth <= g.h) nearOff += got > truth + 1e-3 * g.h;
      errors.push_back((got - truth) / g.h);
      wrongSign += (f.values[idx] < 0) != winding.Inside(p);
    });
    std::sort(errors.begin(), errors.end());
    const double p999 = errors[errors.size() * 999 / 1000], worst = errors.back();
    const long off = std::count_if(errors.begin(), errors.end(), [](double e) { return e > 1e-3; });
    std::printf("[ figures  ] %s, %zu nodes: SDF %.2f s; distance off at %.3f%% of nodes, 99.9th percentile %.1e "
                "cells, max %.1e cells; sign differs from the winding number at %d nodes\n",
                name, errors.size(), seconds, 100.0 * off / errors.size(), p999, worst, wrongSign);
    EXPECT_EQ(below, 0);
    EXPECT_EQ(nearOff, 0);
    EXPECT_LT(worst, 0.35);
    EXPECT_EQ(wrongSign, 0);
  }
}

} // namespace
} // namespace eulermap
