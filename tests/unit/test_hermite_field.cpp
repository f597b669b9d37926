// HermiteField (hermite_field.h): exact on the polynomials it is built for, and a zero
// level set far nearer the surface than trilinear interpolation gives on a coarse grid.
#include "core/closest.h"
#include "core/hermite_field.h"
#include "core/sdf.h"
#include "core/tracker.h"
#include "tests/support/meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace eulermap {
namespace {

using testing::MakeSphere;

// f = 1 + 2x - y + z/2 + xyz + x^2 - y^3 + x z^2: cubic in each axis, with mixed terms whose
// derivatives the central differences of the gradient give exactly.
double Polynomial(const Point3 &p) {
  const double x = p.X(), y = p.Y(), z = p.Z();
  return 1 + 2 * x - y + z / 2 + x * y * z + x * x - y * y * y + x * z * z;
}
Point3 PolynomialGradient(const Point3 &p) {
  const double x = p.X(), y = p.Y(), z = p.Z();
  return Point3(2 + y * z + 2 * x + z * z, -1 + x * z - 3 * y * y, 0.5 + x * y + 2 * x * z);
}

TEST(HermiteField, ReproducesACubicAndItsGradient) {
  const Grid grid = Grid::Enclosing(Box3(Point3(-1, -1, -1), Point3(1, 1, 1)), 6, 1);
  ScalarField f(grid, 0.0);
  VectorField g(grid, Point3(0, 0, 0));
  grid.ForEachNode([&](int i, int j, int k, std::size_t n) {
    f.values[n] = Polynomial(grid.Node(i, j, k));
    g.values[n] = PolynomialGradient(grid.Node(i, j, k));
  });
  const HermiteField hermite(f, g);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> in(-0.99, 0.99);
  double valueError = 0, gradientError = 0, trilinearError = 0;
  for (int s = 0; s < 2000; ++s) {
    const Point3 p(in(random), in(random), in(random));
    Point3 gradient;
    valueError = std::max(valueError, std::abs(hermite.Value(p, &gradient) - Polynomial(p)));
    gradientError = std::max(gradientError, vcg::Distance(gradient, PolynomialGradient(p)));
    trilinearError = std::max(trilinearError, std::abs(f.Value(p) - Polynomial(p)));
  }
  EXPECT_LT(valueError, 1e-10);
  EXPECT_LT(gradientError, 1e-9);
  EXPECT_GT(trilinearError, 0.05);  // the polynomial is not one trilinear interpolation reproduces
}

// A sphere of radius 1 on a grid of 8 cells across its box (cell 0.25): points pulled onto the
// zero level set of its SDF, from 0.2 cells off the surface on either side.
TEST(HermiteField, ZeroLevelSetOfACoarseSphereLiesOnTheSphere) {
  Mesh sphere;
  MakeSphere(sphere, Point3(0.1, -0.05, 0.03), 1, 6);
  const Grid grid = Grid::Enclosing(sphere.bbox, 8);
  VectorField gradient;
  const ScalarField f = SignedDistance(sphere, grid, &gradient);
  const HermiteField hermite(f, gradient);
  const ClosestPoint surface(sphere);
  double trilinear = 0, cubic = 0;
  for (std::size_t n = 0; n < sphere.vert.size(); n += 7) {
    const Point3 &v = sphere.vert[n].cP();
    const Point3 off = v + sphere.vert[n].cN() * (n % 2 ? 0.2 : -0.2) * grid.h;
    trilinear = std::max(trilinear, surface.Query(PullBack(f, off, 0)).distance / grid.h);
    cubic = std::max(cubic, surface.Query(PullBack(hermite, off, 0)).distance / grid.h);
  }
  RecordProperty("trilinear_cells", std::to_string(trilinear));
  RecordProperty("hermite_cells", std::to_string(cubic));
  std::printf("largest distance of the zero level set from the sphere: trilinear %.4f cells, Hermite %.4f cells\n",
              trilinear, cubic);
  EXPECT_LT(cubic, 0.06);  // the mesh's facets are part of it (6 subdivisions of an icosahedron)
  EXPECT_LT(cubic, trilinear / 4);
}

// Near the surface, the gradient SignedDistance gives is the unit vector from the nearest
// surface point, turned round inside.
TEST(HermiteField, SignedDistanceGradientIsTheUnitNormalDirection) {
  Mesh sphere;
  MakeSphere(sphere, Point3(0, 0, 0), 1, 5);
  const Grid grid = Grid::Enclosing(sphere.bbox, 16);
  VectorField gradient;
  const ScalarField f = SignedDistance(sphere, grid, &gradient);
  double error = 0;
  grid.ForEachNode([&](int i, int j, int k, std::size_t n) {
    const Point3 p = grid.Node(i, j, k);
    if (std::abs(f.values[n]) > grid.h) return;  // farther, the face found may be a near one (distance_transform.h)
    error = std::max(error, vcg::Distance(gradient.values[n], p / p.Norm()));
  });
  EXPECT_LT(error, 0.05);  // the mesh's facets: 5 subdivisions of an icosahedron
  EXPECT_EQ(f.values.size(), gradient.values.size());
}

} // namespace
} // namespace eulermap
