// eulermap::BlockMultigrid — a geometric multigrid V-cycle for the velocity system (*) of
// velocity.h, the preconditioner of its conjugate gradients.
//
// The system, per node i with n_i grid neighbours j:
//
//   (D_i + alpha n_i I) V_i - alpha sum_j V_j = b_i,    D_i = g_i g_i^T + beta_i I,
//
// a 3x3 block per node (the data term couples V's components at a node) plus a vector
// Laplacian (the smoothness term couples nodes, each component alike). Gauss-Seidel on
// this system (the paper's Eq. 5) removes the node-local error fast but the smooth error
// of the Laplacian slowly: 90-160 conjugate-gradient iterations a step with a block-
// Jacobi preconditioner at 64 cells. Multigrid removes the smooth part on coarser grids.
//
// Levels: grid l+1 keeps every second node of grid l in each axis, with d_l+1 = d_l/2 + 1
// nodes along an axis of d_l nodes (for even d_l the last coarse node lies one fine cell
// past the box; it only carries the interpolation of the last fine node). Transfers:
// prolongation P, trilinear (a fine node between coarse nodes takes their mean); restriction
// R = P^T / 8, full weighting. Coarse operator by re-discretisation, consistent with the
// Galerkin product P^T A P / 8 for smooth fields: D on the coarse grid is R D (lumped), and
// alpha becomes alpha / 4 (the energy of a linear field: a coarse grid has 1/8 the nodes
// and edges 2 cells long, 4 times the squared difference).
//
// One V-cycle: on each level, a red-black block Gauss-Seidel sweep (red then black),
// the residual restricted to the next level, the correction prolonged back, a sweep in
// the reverse order (black then red) (two sweeps each way: 134 iterations instead of 182
// on Table 1 row 1, but 28% more time); on the coarsest level (at most kCoarsestNodes nodes
// or an axis of at most 4 nodes) 20 sweeps, then the same in reverse. The post-smoother is
// the adjoint of the pre-smoother, so the cycle is a symmetric positive definite operator,
// as preconditioned conjugate gradients need. Work the cycle can skip, with the same result
// (up to rounding): the first red sweep starts from x = 0 (no neighbours to read);
// after the black sweep the residual vanishes at black nodes, so it is computed at red nodes
// only and the full weighting reads 13 of its 27 fine nodes (the coarse nodes are red, the
// other 14 black); the post-smoother's black sweep overwrites black nodes without reading
// them, so the correction is prolonged onto red nodes only. The finest level stores no
// blocks: its block g g^T + (alpha n_i + beta_i) I is inverted by the Sherman-Morrison
// formula from the solver's g and shift (16 bytes a node read, against 24 for a stored
// inverse; no D, inverse or diagonal kept at 60 bytes a node), its iterate is the solver's z
// and its right-hand side the solver's r. Levels store their values
// split by colour (red_black.h), so that sweeps run vectorised over contiguous rows.
#pragma once

#include "field.h"
#include "interrupt.h"
#include "red_black.h"

#include <vector>

namespace eulermap {

// Blocks D_i and their inverses are symmetric 3x3 matrices, stored as 6 components (xx, xy,
// xz, yy, yz, zz) in single precision (half the memory traffic of double), as are the
// vectors of the conjugate gradients around the preconditioner (velocity.h).
class BlockMultigrid {
 public:
  // in:  the grid (its node counts set the levels), alpha; interrupt, asked while each
  //      level's arrays are filled (its answer is left to the caller). Allocates every level once;
  //      the operator is set by Update, step after step.
  BlockMultigrid(const Grid &grid, double alpha, const Interrupt &interrupt = Interrupt());

  const vcg::Point3i &Dims() const { return levels_.front().dims; }
  // in:  the finest grid's system, in RedBlackLayout(Dims()) (ghosts 0): per node g_i and
  //      shift_i = alpha n_i + beta_i, its block being g g^T + shift I (read by every V-cycle
  //      until the next Update, not copied: they must stay alive and unchanged till then), and
  //      beta_i (null: 0; read here only: it may be borrowed storage)
  // out: the coarse levels' D (the first one's restricted from D_i = g g^T + beta_i I, formed
  //      tap by tap) and their block inverses. The finest level stores no blocks: its sweeps
  //      invert g g^T + shift I by the Sherman-Morrison formula, from g and shift.
  void Update(const RedBlackArrays<3> &g, const RedBlackArrays<1> &shift, const RedBlackArrays<1> *beta = nullptr);

  // in:  r on the finest grid, in RedBlackLayout(Dims()) (ghosts 0); interrupt, asked before
  //      the cycle and between the finest level's pieces (smoothing, restriction, the coarse
  //      levels: each a pass or more over the grid), its answer left to the caller
  // out: z = M^-1 r, one V-cycle from z = 0, in the same layout (ghosts 0: never written;
  //      z is the finest level's iterate, so it must not be r); returns r . z
  //      (summed by plane, in order: the same bits for any number of threads)
  double Precondition(const RedBlackArrays<3> &r, RedBlackArrays<3> &z, const Interrupt &interrupt = Interrupt());

  int Levels() const { return int(levels_.size()); }

 private:
  struct Level {
    vcg::Point3i dims;
    double alpha = 0;
    RedBlackLayout layout;         // of the arrays below
    // Coarse levels only (the finest one's blocks come from g and shift, Update):
    RedBlackArrays<6> data;        // D_i
    RedBlackArrays<1> shift;       // alpha n_i
    RedBlackArrays<6> inverse;     // (D_i + alpha n_i I)^-1, (xx, xy, xz, yy, yz, zz)
    RedBlackArrays<6> diagonal;    // D_i + alpha n_i I (red nodes only: the residual's)
    RedBlackArrays<3> ownX, ownB;  // the iterate and the right-hand side (the restricted residual)
    // Every level:
    RedBlackArrays<3> r;           // the residual, red nodes only
    RedBlackArrays<3> *x = nullptr;        // ownX, or the finest level's z (Precondition)
    const RedBlackArrays<3> *b = nullptr;  // ownB, or the finest level's r (Precondition)
    std::vector<float> gathered[3];  // x in Grid::Index order (coarse levels: the prolongation's)
    std::size_t Count() const { return std::size_t(dims[0]) * dims[1] * dims[2]; }
  };

  // x = (D + alpha n I)^-1 (b + alpha sum_j x_j) at the nodes of colour c (fromZero: every
  // x_j taken as 0, for the first sweep of a cycle); plane (when given): b . x over the swept
  // nodes added by plane (each plane's runs in order, by one thread).
  void Sweep(Level &l, int c, bool fromZero, std::vector<double> *plane = nullptr);
  void Residual(Level &l);                            // l.r = l.b - A l.x at red nodes
  void ProlongAdd(Level &coarse, Level &fine);  // fine.x += P coarse.x at red nodes
  // plane (when given): b . x of the level's last sweeps, by plane; interrupt (when given)
  // asked between the level's pieces.
  void Cycle(std::size_t level, std::vector<double> *plane = nullptr, const Interrupt *interrupt = nullptr);

  std::vector<Level> levels_;
  // The finest level's system (Update).
  const RedBlackArrays<3> *g_ = nullptr;
  const RedBlackArrays<1> *shift_ = nullptr;
};

} // namespace eulermap
