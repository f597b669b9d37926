// The multigrid V-cycle (multigrid.h) on a problem with a known solution: the velocity
// system's operator with D_i = beta I (a screened vector Poisson problem), right-hand side
// b = A x* for a smooth x*. Claims: each V-cycle cuts the residual by a fixed factor
// whatever the grid, the iteration reaches x*, and the cycle is a symmetric positive
// definite operator (what conjugate gradients need of a preconditioner).
#include "core/multigrid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

using namespace eulermap;

namespace {

constexpr double kAlpha = 2, kBeta = 0.05;

struct Problem {
  Grid grid;
  RedBlackLayout layout;
  BlockMultigrid multigrid;
  RedBlackArrays<3> g;      // 0
  RedBlackArrays<1> shift;  // alpha n_i + beta

  explicit Problem(int nodes)
      : grid(Grid::WithNodes(Box3(Point3(0, 0, 0), Point3(1, 1, 1)), vcg::Point3i(nodes, nodes, nodes), 0)),
        layout(grid.dims), multigrid(grid, kAlpha) {
    RedBlackArrays<1> beta;
    beta.Resize(layout), g.Resize(layout), shift.Resize(layout);
    grid.ForEachNode([&](int i, int j, int k, std::size_t) {
      const int c = RedBlackLayout::Colour(i, j, k);
      const std::size_t m = layout.Position(i, j, k);
      beta.c[c][0][m] = float(kBeta);
      shift.c[c][0][m] = float(kAlpha * layout.NeighbourCount(i, j, k) + kBeta);
    });
    multigrid.Update(g, shift, &beta);
  }

  // (A x)_i = (beta + alpha n_i) x_i - alpha sum_j x_j over the grid neighbours j, per component.
  std::vector<Point3> Apply(const std::vector<Point3> &x) const {
    std::vector<Point3> out(x.size());
    const vcg::Point3i d = grid.dims;
    grid.ForEachNode([&](int i, int j, int k, std::size_t n) {
      Point3 sum(0, 0, 0);
      int count = 0;
      const int c[3] = {i, j, k};
      for (int a = 0; a < 3; ++a)
        for (int s : {-1, 1}) {
          int e[3] = {c[0], c[1], c[2]};
          e[a] += s;
          if (e[a] < 0 || e[a] >= d[a]) continue;
          sum += x[grid.Index(e[0], e[1], e[2])];
          ++count;
        }
      out[n] = x[n] * (kBeta + kAlpha * count) - sum * kAlpha;
    });
    return out;
  }

  // z = M^-1 r through the layout's arrays; returns r . z as Precondition gives it.
  double Precondition(const std::vector<Point3> &r, std::vector<Point3> &z, const Interrupt &interrupt = Interrupt()) {
    RedBlackArrays<3> rr, zz;
    rr.Resize(layout);
    zz.Resize(layout);
    grid.ForEachNode([&](int i, int j, int k, std::size_t n) {
      for (int a = 0; a < 3; ++a) rr.c[RedBlackLayout::Colour(i, j, k)][a][layout.Position(i, j, k)] = r[n][a];
    });
    const double rz = multigrid.Precondition(rr, zz, interrupt);
    z.assign(r.size(), Point3(0, 0, 0));
    grid.ForEachNode([&](int i, int j, int k, std::size_t n) {
      for (int a = 0; a < 3; ++a) z[n][a] = zz.c[RedBlackLayout::Colour(i, j, k)][a][layout.Position(i, j, k)];
    });
    return rz;
  }

  // A smooth field: products of sines and cosines over the unit box.
  std::vector<Point3> Smooth() const {
    std::vector<Point3> x(grid.NodeCount());
    grid.ForEachNode([&](int i, int j, int k, std::size_t n) {
      const Point3 p = grid.Node(i, j, k);
      x[n] = Point3(std::sin(M_PI * p.X()) * std::cos(2 * p.Y()), std::cos(M_PI * p.Z()) + p.X(),
                    std::sin(3 * p.Y()) * std::sin(2 * p.Z()));
    });
    return x;
  }
};

double Norm(const std::vector<Point3> &x) {
  double s = 0;
  for (const Point3 &p : x) s += p.SquaredNorm();
  return std::sqrt(s);
}

std::vector<Point3> Minus(const std::vector<Point3> &a, const std::vector<Point3> &b) {
  std::vector<Point3> d(a.size());
  for (std::size_t n = 0; n < a.size(); ++n) d[n] = a[n] - b[n];
  return d;
}

// x <- x + M^-1 (b - A x), `cycles` times from x = 0; the residual norms, the first ||b||.
std::vector<double> Iterate(Problem &p, const std::vector<Point3> &b, std::vector<Point3> &x, int cycles) {
  x.assign(b.size(), Point3(0, 0, 0));
  std::vector<double> residuals{Norm(b)};
  std::vector<Point3> z;
  for (int n = 0; n < cycles; ++n) {
    p.Precondition(Minus(b, p.Apply(x)), z);
    for (std::size_t m = 0; m < x.size(); ++m) x[m] += z[m];
    residuals.push_back(Norm(Minus(b, p.Apply(x))));
  }
  return residuals;
}

// The largest residual reduction of one V-cycle over 10 cycles (the factor grows towards
// the slowest mode's as the others die out).
double WorstFactor(int nodes) {
  Problem p(nodes);
  std::vector<Point3> x;
  const std::vector<double> r = Iterate(p, p.Apply(p.Smooth()), x, 10);
  double worst = 0;
  for (std::size_t n = 1; n < r.size(); ++n) worst = std::max(worst, r[n] / r[n - 1]);
  std::printf("%d^3: worst residual factor of a V-cycle %.3f\n", nodes, worst);
  return worst;
}

// A smoother alone slows down as the grid grows (its factor tends to 1 with the square of the
// node count along an axis); the V-cycle's stays below a bound.
TEST(Multigrid, EachVCycleCutsTheResidualByAFactorBoundedOverGrids) {
  for (int nodes : {17, 33, 65}) EXPECT_LT(WorstFactor(nodes), 0.55) << nodes << "^3";
}

TEST(Multigrid, TheIterationReachesTheKnownSolution) {
  Problem p(25);
  const std::vector<Point3> solution = p.Smooth();
  std::vector<Point3> x;
  Iterate(p, p.Apply(solution), x, 12);
  // The cycle works in single precision: 1e-4 of the solution is well above its rounding.
  EXPECT_LT(Norm(Minus(x, solution)) / Norm(solution), 1e-4);
}

TEST(Multigrid, TheCycleIsSymmetricPositiveDefinite) {
  Problem p(21);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  std::vector<Point3> u(p.grid.NodeCount()), v(u.size()), Mu, Mv;
  for (std::size_t n = 0; n < u.size(); ++n) {
    u[n] = Point3(uniform(random), uniform(random), uniform(random));
    v[n] = Point3(uniform(random), uniform(random), uniform(random));
  }
  EXPECT_GT(p.Precondition(u, Mu), 0);
  EXPECT_GT(p.Precondition(v, Mv), 0);
  double uMv = 0, vMu = 0;
  for (std::size_t n = 0; n < u.size(); ++n) uMv += u[n] * Mv[n], vMu += v[n] * Mu[n];
  EXPECT_NEAR(uMv, vMu, 1e-4 * std::abs(uMv) + 1e-6 * Norm(u) * Norm(Mv));
}

// Progress on big grids (interrupt.h): a V-cycle asks at its start, between the two colours
// of each smoothing of the finest level (half its nodes each, the longest pieces of the
// cycle), after its pre-smoothing, after the residual's restriction and after the coarse
// levels: 6 calls (4 before the calls between the colours).
TEST(Multigrid, ACycleAsksAfterEachColourOfTheFinestLevel) {
  Problem p(33);
  int calls = 0;
  const Interrupt counting([&] { return ++calls, true; });
  std::vector<Point3> z;
  p.Precondition(p.Smooth(), z, counting);
  EXPECT_GE(calls, 6);
}

} // namespace
