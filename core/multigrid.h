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
// as preconditioned conjugate gradients need.
#pragma once

#include "field.h"

#include <vector>

namespace eulermap {

// A symmetric 3x3 matrix, in single precision (the preconditioner's storage: half the
// memory traffic of double; the conjugate gradients around it stay in double).
struct Sym3 {
  float xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;

  vcg::Point3f operator*(const vcg::Point3f &v) const {
    return vcg::Point3f(xx * v[0] + xy * v[1] + xz * v[2], xy * v[0] + yy * v[1] + yz * v[2],
                        xz * v[0] + yz * v[1] + zz * v[2]);
  }
  // The inverse of this + c I (positive definite), computed in double.
  Sym3 ShiftedInverse(double c) const;
};

class BlockMultigrid {
 public:
  // in:  the grid (its node counts set the levels), alpha. Allocates every level once;
  //      the operator is set by Update, step after step.
  BlockMultigrid(const Grid &grid, double alpha);

  const vcg::Point3i &Dims() const { return levels_.front().dims; }
  // D_i per node of the finest grid (Grid::Index order): fill it, then call Update.
  std::vector<Sym3> &Data() { return levels_.front().data; }
  // out: the coarse levels' D and every level's block inverses, from Data()
  void Update();

  // out: z = M^-1 r, one V-cycle from z = 0
  void Precondition(const std::vector<Point3> &r, std::vector<Point3> &z);

  int Levels() const { return int(levels_.size()); }

 private:
  struct Level {
    vcg::Point3i dims;
    double alpha = 0;
    std::vector<Sym3> data;     // D_i
    std::vector<Sym3> inverse;  // (D_i + alpha n_i I)^-1
    std::vector<vcg::Point3f> x, b, r;
    std::size_t Index(int i, int j, int k) const { return i + std::size_t(dims[0]) * (j + std::size_t(dims[1]) * k); }
    std::size_t Count() const { return std::size_t(dims[0]) * dims[1] * dims[2]; }
  };

  void Sweep(Level &l, int colour);
  void Residual(Level &l);                    // l.r = l.b - A l.x
  void Restrict(const Level &fine, const std::vector<vcg::Point3f> &in, Level &coarse, std::vector<vcg::Point3f> &out);
  void RestrictData(const Level &fine, Level &coarse);
  void ProlongAdd(const Level &coarse, Level &fine);  // fine.x += P coarse.x
  void Cycle(std::size_t level);

  std::vector<Level> levels_;
};

} // namespace eulermap
