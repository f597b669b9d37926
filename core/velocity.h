// eulermap::VelocitySolver — the velocity field V_k of one time step (Eqs. 2-5).
//
// V_k minimises the discrete form of Eq. 2 on the grid nodes,
//
//   E(V) = sum_nodes (g . V + f_t)^2 + alpha * sum_grid_edges |V_i - V_j|^2
//          + sum_nodes beta_i |V - P|^2,
//
// with g = grad f and f_t = df/dt taken between the frames f(., t_k) and f(., t_k+1)
// (g of their mean, f_t their difference over dt). The smoothness term is |grad V|^2
// with derivatives in grid units, so alpha does not depend on the model's size. Setting
// dE/dV_i = 0 gives, per node i with n_i grid neighbours (Eqs. 3-4, with Eq. 3's third
// line reading f_z f_t),
//
//   (g g^T + alpha n_i I) V_i - alpha sum_j V_j = -g f_t,                     (*)
//
// The last term is ours, not the paper's: P is the velocity the anchors impose
// (Morph::AnchorMotion), beta_i a weight that is large near the moving anchors q_i(t)
// and vanishes away from them. The data term fixes V's normal part; near an anchor its
// own motion (which stays on the zero level set, as f(q_i(t), t) = 0) settles the
// tangential part too, which Eq. 2 alone leaves to smoothness, so anchor points land
// on their partners. Without anchors beta = 0 (the paper's Eq. 2). With it (*) reads
// (g g^T + (alpha n_i + beta_i) I) V_i - alpha sum_j V_j = -g f_t + beta_i P_i,
// a symmetric positive definite system. Three solvers:
//   - Gauss-Seidel, the paper's update (Eq. 5, derived from (*) with one alpha, by the
//     Sherman-Morrison formula): V_i = Vbar - g (g . Vbar + f_t) / (alpha n_i + |g|^2),
//     Vbar = sum_j V_j / n_i; red-black ordering so that both colours run in parallel;
//   - conjugate gradients preconditioned by the exact inverse of each node's 3x3 block;
//   - conjugate gradients preconditioned by a multigrid V-cycle (multigrid.h), the default.
// All start from the V passed in (the previous step's: a warm start); the conjugate gradients
// move it along d = V_k-1 - V_k-2 (the start of the solve before) to the least error energy
// on that line: x = V_k-1 + theta d, theta = r . d / d . A d. Where V changes smoothly from
// step to step theta is near 1 (the linear extrapolation in time), and the start is never
// worse than V_k-1 in the energy norm.
#pragma once

#include "field.h"
#include "interrupt.h"
#include "multigrid.h"

#include <functional>
#include <memory>

namespace eulermap {

struct VelocitySolve {
  int iterations = 0;
  double residual = 0;  // ||b - A V|| / ||b|| at the end, b = -g f_t
};

class VelocitySolver {
 public:
  enum class Method { Multigrid, ConjugateGradient, GaussSeidel };

  VelocitySolver(double alpha, Method method, double tolerance, int maxIterations)
      : alpha_(alpha), method_(method), tolerance_(tolerance), maxIterations_(maxIterations) {}

  // in:  frames fk = f(., t_k), fk1 = f(., t_k + dt) on one grid; V, the start (resized
  //      and zeroed when its grid differs); prior P and its weights beta on the same
  //      grid, or empty fields for none; interrupt, asked once the first step's arrays are
  //      allocated, every kNodesBetweenPolls nodes of the assembly and once it is done, before
  //      each iteration and each V-cycle, and at the end (interrupt.h)
  // out: V = V_k, and the solve's figures; where the interrupt stops it, the iterate it had
  VelocitySolve Solve(const ScalarField &fk, const ScalarField &fk1, double dt, VectorField &V,
                      const VectorField &prior = VectorField(), const ScalarField &priorWeight = ScalarField(),
                      const Interrupt &interrupt = Interrupt());

 private:
  // Vectors of the system: one point per node, split by colour (red_black.h), in single
  // precision (half the memory and its traffic: the solve is bound by it); sums and the
  // solver's scalars in double.
  using Vectors = RedBlackArrays<3>;

  // Both need bNorm = ||b|| > 0; x: the start, then the solution. precondition(r, z): z = M^-1 r,
  // returns r . z.
  VelocitySolve SolveConjugateGradient(Vectors &x, double bNorm, const std::function<double(const Vectors &, Vectors &)> &precondition,
                                       const Interrupt &interrupt);
  VelocitySolve SolveGaussSeidel(Vectors &x, double bNorm, const Interrupt &interrupt);
  // r = b - A x, with ax = A x on the way (r may be b or ax); returns ||r||.
  double Residual(const Vectors &x, const Vectors &b, Vectors &r, Vectors &ax) const;
  // out = A x (the operator of (*)); returns x . A x.
  double Apply(const Vectors &x, Vectors &out) const;
  // z = the exact inverse of each node's block g g^T + (alpha n_i + beta_i) I times r; returns r . z.
  double BlockJacobi(const Vectors &r, Vectors &z) const;

  double alpha_;
  Method method_;
  double tolerance_;
  int maxIterations_;
  // Per-step data of (*), in layout_: g and shift = alpha n_i + beta_i per node. The
  // right-hand side b = -g f_t + beta P is assembled into r_ (conjugate gradients: r = b - A x
  // in place; Gauss-Seidel: b moved to p_, which it does not use otherwise).
  Grid grid_;
  RedBlackLayout layout_;
  Vectors g_;
  RedBlackArrays<1> shift_;
  // Kept from step to step (same grid): the multigrid levels and the solvers' vectors (the
  // preconditioned residual z shares q's: q = A p is dead once r is updated; the prior's
  // weights, which the multigrid reads once a step, borrow p's storage before the solve).
  std::unique_ptr<BlockMultigrid> multigrid_;
  Vectors x_, r_, p_, q_;
  // V_k-2, the start of the last solve (during the assembly and the start: d = V_k-1 - V_k-2).
  Vectors previous_;
};

} // namespace eulermap
