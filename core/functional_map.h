// eulermap::ComputeLaplaceBasis and eulermap::ZoomOut — a pointwise map refined in the
// spectral domain, for the anchors a map is made again through (pipeline.cpp,
// AddAnchorsFromMap).
//
// The basis: the first k eigenfunctions of the cotangent Laplace–Beltrami operator,
// L phi = lambda M phi (L the cotangent stiffness matrix, M the lumped (barycentric) mass
// matrix, the mesh scaled to unit area), by shift-invert Lanczos with full
// reorthogonalisation. ZoomOut (Melzi, Ren, Rodolà, Sharma, Wonka and Ovsjanikov,
// "ZoomOut: spectral upsampling for efficient shape correspondence", SIGGRAPH Asia 2019):
// from a pointwise map T, the functional map C_k of k basis functions that T induces, then
// the pointwise map that C_k induces, k growing step by step.
#pragma once

#include "interrupt.h"
#include "mesh.h"

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace eulermap {

struct LaplaceBasis {
  Eigen::MatrixXd phi;     // vertices x k, M-orthonormal (phi^T M phi = I), columns by ascending lambda
  Eigen::VectorXd lambda;  // the eigenvalues, ascending (0 first for each closed component)
  Eigen::VectorXd mass;    // the lumped mass of each vertex, the mesh scaled to unit area
};

// The first min(k, vertices) eigenpairs of L phi = lambda M phi on `mesh` scaled to unit area.
// Unreferenced vertices get a tiny mass and no stiffness; clean them before (input.h does).
// `interrupt` is asked before each Lanczos step (a few milliseconds on a 12k-vertex scan); where
// it stops, phi has no columns.
LaplaceBasis ComputeLaplaceBasis(const Mesh &mesh, int k, const Interrupt &interrupt = Interrupt());

// in:  the two bases, source vertices `samples`, the share of the source's area each stands
//      for (`weights`), the target vertices the maps between refinements choose among
//      (`candidates`), and the target vertex of each sample under the map to refine (`map`),
//      the numbers of basis functions (from, from + step, ..., to; to at most either
//      basis' size), and source vertices `query`
// out: the target vertex (any, not only a candidate) of each query vertex under the
//      pointwise map of the last functional map. Each C_k (k x k) solves phi_source[samples] C_k = phi_target[map] in the
//      least-squares sense weighted by area (ZoomOut's Eq. 2 with the mass matrix, the
//      samples' area standing for their neighbours'): C_k carries a function's coefficients
//      on the target to those of its pull-back on the source. Its pointwise map sends a source
//      vertex v to the target vertex w whose row phi_target(w) C_k^T lies nearest to
//      phi_source(v) (ZoomOut's Eq. 3; C_k^T stands for C_k^-1, as an isometry's functional map
//      is orthogonal). The other way round, phi_source(v) C_k against phi_target(w), the read
//      anchors of TOPKIDS kid01 lie 3.96 x 100 from the truth on mean instead of 2.46 (pyFM's).
//      `interrupt` is asked before each k; where it stops, the result is empty.
std::vector<std::size_t> ZoomOut(const LaplaceBasis &source, const LaplaceBasis &target,
                                 const std::vector<std::size_t> &samples, const Eigen::VectorXd &weights,
                                 const std::vector<std::size_t> &candidates, std::vector<std::size_t> map, int from,
                                 int to, int step, const std::vector<std::size_t> &query,
                                 const Interrupt &interrupt = Interrupt());

}  // namespace eulermap
