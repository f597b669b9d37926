// Velocity field of Eqs. 2-5: the solvers reach the tolerance on the system (*) of
// velocity.h, agree with each other, and a uniformly growing sphere gives a radial
// field with the growth speed.
#include "core/velocity.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace eulermap;

namespace {

// f(p, t) = |p - c| - (r0 + speed t), sampled on a 40^3 grid of unit cells.
ScalarField GrowingSphere(const Grid &grid, double r0, double speed, double t) {
  ScalarField f(grid, 0.0);
  const Point3 c = grid.Bounds().Center();
  grid.ForEachNode([&](int i, int j, int k, std::size_t n) { f.values[n] = vcg::Distance(grid.Node(i, j, k), c) - (r0 + speed * t); });
  return f;
}

Grid UnitGrid(int nodes) {
  Grid g;
  g.origin = Point3(0, 0, 0);
  g.h = 1;
  g.dims = vcg::Point3i(nodes, nodes, nodes);
  return g;
}

// ||b - A V|| / ||b|| recomputed here from (*), independently of the solver's own figure.
double Residual(const ScalarField &fk, const ScalarField &fk1, double dt, const VectorField &V, double alpha) {
  const Grid &g = fk.grid;
  double r2 = 0, b2 = 0;
  g.ForEachNode([&](int i, int j, int k, std::size_t n) {
    const Point3 grad = (fk.NodeGradient(i, j, k) + fk1.NodeGradient(i, j, k)) * 0.5;
    const Point3 b = grad * -((fk1.values[n] - fk.values[n]) / dt);
    Point3 av = grad * (grad * V.values[n]);
    const int idx[3] = {i, j, k};
    for (int a = 0; a < 3; ++a)
      for (int s = -1; s <= 1; s += 2) {
        int nb[3] = {i, j, k};
        nb[a] += s;
        if (nb[a] < 0 || nb[a] >= g.dims[a]) continue;
        av += (V.values[n] - V(nb[0], nb[1], nb[2])) * alpha;
      }
    (void)idx;
    r2 += (b - av).SquaredNorm();
    b2 += b.SquaredNorm();
  });
  return std::sqrt(r2 / b2);
}

} // namespace

// The three solvers of velocity.h reach the tolerance on the true residual and give the
// same field; multigrid needs the fewest iterations (a V-cycle costs about 5 CG iterations).
// The vectors are single precision: the conjugate gradients' updated residual drifts from
// the true one by rounding (at 1e-6, true residuals of 1.2e-6 and 2.5e-6), so the test asks
// 1e-5, ten times finer than the maps' 1e-4 (options.h), and the true residual within 10%.
TEST(Velocity, AllSolversReachTheToleranceAndAgree) {
  const Grid grid = UnitGrid(32);
  const double dt = 1.0 / 40, alpha = 2, tolerance = 1e-5;
  const ScalarField fk = GrowingSphere(grid, 8, 6, 0.5), fk1 = GrowingSphere(grid, 8, 6, 0.5 + dt);
  VectorField mg, cg, gs;
  const VelocitySolve sm = VelocitySolver(alpha, VelocitySolver::Method::Multigrid, tolerance, 2000).Solve(fk, fk1, dt, mg);
  const VelocitySolve sc = VelocitySolver(alpha, VelocitySolver::Method::ConjugateGradient, tolerance, 2000).Solve(fk, fk1, dt, cg);
  const VelocitySolve sg = VelocitySolver(alpha, VelocitySolver::Method::GaussSeidel, tolerance, 20000).Solve(fk, fk1, dt, gs);
  for (const VelocitySolve &s : {sm, sc, sg}) EXPECT_LE(s.residual, tolerance);
  for (const VectorField *v : {&mg, &cg, &gs}) EXPECT_LE(Residual(fk, fk1, dt, *v, alpha), 1.1 * tolerance);
  double worst = 0, largest = 0;
  for (std::size_t n = 0; n < cg.values.size(); ++n) {
    worst = std::max({worst, (cg.values[n] - gs.values[n]).Norm(), (mg.values[n] - cg.values[n]).Norm()});
    largest = std::max(largest, cg.values[n].Norm());
  }
  EXPECT_LE(worst, 1e-3 * largest);
  EXPECT_LT(sm.iterations * 5, sc.iterations);
  std::printf("multigrid-CG: %d iterations, block-Jacobi CG: %d iterations, GS: %d sweeps, largest difference %.2e of %.3g\n",
              sm.iterations, sc.iterations, sg.iterations, worst, largest);
}

TEST(Velocity, WarmStartNeedsFewerIterations) {
  const Grid grid = UnitGrid(32);
  const double dt = 1.0 / 40;
  VelocitySolver solver(2, VelocitySolver::Method::ConjugateGradient, 1e-4, 2000);
  VectorField V;
  const VelocitySolve cold = solver.Solve(GrowingSphere(grid, 8, 6, 0.3), GrowingSphere(grid, 8, 6, 0.3 + dt), dt, V);
  const VelocitySolve warm = solver.Solve(GrowingSphere(grid, 8, 6, 0.3 + dt), GrowingSphere(grid, 8, 6, 0.3 + 2 * dt), dt, V);
  EXPECT_LT(warm.iterations, cold.iterations / 2);
  EXPECT_LE(warm.residual, 1e-4);
}

// Progress on big grids (interrupt.h): no piece of work between two calls of the host's
// callback longer than about one pass over the nodes. The conjugate gradients' start is two
// passes (the operator on the last step's change, the residual), each iteration its operator
// then the rest (the preconditioner, the updates): a call after each.
TEST(Velocity, TheConjugateGradientsAskAfterEachPassOverTheNodes) {
  const Grid grid = UnitGrid(32);
  const double dt = 1.0 / 40;
  VelocitySolver solver(2, VelocitySolver::Method::ConjugateGradient, 1e-6, 2000);
  VectorField V;
  solver.Solve(GrowingSphere(grid, 8, 6, 0.3), GrowingSphere(grid, 8, 6, 0.3 + dt), dt, V);  // the arrays allocated
  auto moving = [&](double t) {  // a sphere of radius 8 moving along x at speed 6: not a growth, V far from the last
    ScalarField f(grid, 0.0);
    const Point3 c = grid.Bounds().Center() + Point3(6 * t, 0, 0);
    grid.ForEachNode([&](int i, int j, int k, std::size_t n) { f.values[n] = vcg::Distance(grid.Node(i, j, k), c) - 8; });
    return f;
  };
  int calls = 0;
  const Interrupt counting([&] { return ++calls, true; });
  const VelocitySolve s = solver.Solve(moving(0.3), moving(0.3 + dt), dt, V, {}, {}, counting);
  ASSERT_GT(s.iterations, 5);
  EXPECT_GE(calls, 2 + 2 * s.iterations);
}

TEST(Velocity, GrowingSphereGivesARadialFieldWithTheGrowthSpeed) {
  const Grid grid = UnitGrid(40);
  const double dt = 1.0 / 40, speed = 6, r0 = 9;
  const ScalarField fk = GrowingSphere(grid, r0, speed, 0.5), fk1 = GrowingSphere(grid, r0, speed, 0.5 + dt);
  VectorField V;
  VelocitySolver(2, VelocitySolver::Method::ConjugateGradient, 1e-6, 2000).Solve(fk, fk1, dt, V);
  const Point3 c = grid.Bounds().Center();
  double worstAngle = 0, worstSpeed = 0;
  int near = 0;
  grid.ForEachNode([&](int i, int j, int k, std::size_t n) {
    const double f = 0.5 * (fk.values[n] + fk1.values[n]);
    if (std::abs(f) > 1) return;  // nodes within one cell of the moving surface
    ++near;
    const Point3 radial = (grid.Node(i, j, k) - c).Normalize();
    const Point3 v = V.values[n];
    worstAngle = std::max(worstAngle, std::acos(std::min(1.0, v * radial / v.Norm())));
    worstSpeed = std::max(worstSpeed, std::abs(v * radial - speed) / speed);
  });
  std::printf("%d nodes near the surface: worst angle %.3f deg, worst speed error %.2f%%\n", near, worstAngle * 180 / M_PI,
              100 * worstSpeed);
  EXPECT_GT(near, 1000);
  EXPECT_LT(worstAngle * 180 / M_PI, 1.0);
  EXPECT_LT(worstSpeed, 0.05);
}
