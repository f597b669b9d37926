// The unsigned distance by closest-face propagation (distance_transform.h) against a brute
// force over every face at every node, on small grids: never below the true distance, exact
// within one cell of the surface, and at most 0.35 cells above it anywhere (the header's
// worst measured figure is 0.30 cells, at a sphere's centre); the gradient is a unit vector
// that leads from the node back onto the surface; a mesh without faces gives zeros.
#include "core/distance_transform.h"
#include "tests/support/meshes.h"

#include <vcg/space/distance3.h>
#include <vcg/space/triangle3.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

using namespace eulermap;
using namespace eulermap::testing;

namespace {

// "Exact", in cells: the distances may be stored in single precision.
constexpr double kExact = 1e-4;

// Distance from p to m's nearest live face, trying every face.
double BruteDistance(const Mesh &m, const Point3 &p) {
  double best = std::numeric_limits<double>::max();
  for (const Face &f : m.face) {
    if (f.IsD()) continue;
    double d;
    Point3 q;
    vcg::TrianglePointDistance(vcg::Triangle3<double>(f.cP(0), f.cP(1), f.cP(2)), p, d, q);
    best = std::min(best, d);
  }
  return best;
}

struct Case {
  std::string name;
  Mesh mesh;
  Grid grid;                   // 24 cells on the longest side
  ScalarField distance;        // UnsignedDistance
  std::vector<double> truth;   // the brute force, per node
  std::vector<double> errors;  // (distance - truth) / h, per node
};

// A sphere (curved, its medial axis a point), a box (flat faces, sharp edges) and a torus
// (a medial circle), each measured once for the tests below.
std::vector<Case> &Cases() {
  static std::vector<Case> cases = [] {
    std::vector<Case> c(3);
    c[0].name = "sphere";
    MakeSphere(c[0].mesh, Point3(0.1, -0.2, 0.05), 1, 2);
    c[1].name = "box";
    MakeBox(c[1].mesh, Box3(Point3(-1, -0.5, -0.7), Point3(1, 0.6, 0.7)), 2);
    c[2].name = "torus";
    MakeTorus(c[2].mesh, Point3(0, 0, 0), 1, 0.35, 32, 12, TexCoordKind::None);
    for (Case &one : c) {
      one.grid = Grid::Enclosing(one.mesh.bbox, 24);
      one.distance = UnsignedDistance(one.mesh, one.grid);
      one.truth.resize(one.grid.NodeCount());
      one.errors.resize(one.grid.NodeCount());
      one.grid.ForEachNode([&](int i, int j, int k, std::size_t n) {
        one.truth[n] = BruteDistance(one.mesh, one.grid.Node(i, j, k));
        one.errors[n] = (one.distance.values[n] - one.truth[n]) / one.grid.h;
      });
    }
    return c;
  }();
  return cases;
}

TEST(DistanceTransform, NeverBelowTheTrueDistance) {
  for (const Case &c : Cases()) {
    const std::vector<double> &e = c.errors;
    EXPECT_GE(*std::min_element(e.begin(), e.end()), -kExact) << c.name;
  }
}

TEST(DistanceTransform, ExactWithinOneCellOfTheSurface) {
  for (const Case &c : Cases()) {
    const std::vector<double> &e = c.errors, &truth = c.truth;
    int near = 0, off = 0;
    for (std::size_t n = 0; n < e.size(); ++n)
      if (truth[n] <= c.grid.h) ++near, off += std::abs(e[n]) > kExact;
    EXPECT_GT(near, 100) << c.name;
    EXPECT_EQ(off, 0) << c.name << ": " << off << " of " << near << " nodes within a cell";
  }
}

TEST(DistanceTransform, AtMostAThirdOfACellAboveAnywhere) {
  for (const Case &c : Cases()) {
    const std::vector<double> &e = c.errors;
    const double worst = *std::max_element(e.begin(), e.end());
    const long off = std::count_if(e.begin(), e.end(), [](double x) { return x > 1e-3; });
    std::printf("[ figures  ] %s, %zu nodes: off by over 1e-3 cells at %ld, worst %.3f cells\n", c.name.c_str(),
                e.size(), off, worst);
    EXPECT_LE(worst, 0.35) << c.name;
  }
}

// node - distance * gradient is the nearest point of the face found: on the surface, and the
// gradient has unit length.
TEST(DistanceTransform, TheGradientLeadsBackOntoTheSurface) {
  for (Case &c : Cases()) {
    const Grid g = Grid::Enclosing(c.mesh.bbox, 24);
    VectorField gradient;
    const ScalarField d = UnsignedDistance(c.mesh, g, &gradient);
    ASSERT_EQ(gradient.values.size(), g.NodeCount());
    double worstLength = 0, worstFoot = 0;
    g.ForEachNode([&](int i, int j, int k, std::size_t n) {
      if ((i + j + k) % 5) return;  // a fifth of the nodes: the brute force is slow
      worstLength = std::max(worstLength, std::abs(gradient.values[n].Norm() - 1));
      const Point3 foot = g.Node(i, j, k) - gradient.values[n] * d.values[n];
      worstFoot = std::max(worstFoot, BruteDistance(c.mesh, foot));
    });
    EXPECT_LT(worstLength, kExact) << c.name;
    EXPECT_LT(worstFoot, kExact * g.h) << c.name;
  }
}

TEST(DistanceTransform, AMeshWithoutFacesGivesZeros) {
  Mesh points;
  vcg::tri::Allocator<Mesh>::AddVertices(points, 3);
  const Grid g = Grid::Enclosing(Box3(Point3(0, 0, 0), Point3(1, 1, 1)), 8);
  const ScalarField d = UnsignedDistance(points, g);
  ASSERT_EQ(d.values.size(), g.NodeCount());
  for (double v : d.values) EXPECT_EQ(v, 0);
}

} // namespace
