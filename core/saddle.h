// eulermap::FindSaddles — the saddles of the velocity field (paper Sec. 3.4; DESIGN.md
// settles the paper's index rule). The paper cuts where they meet the surface; here the
// topology events of f decide where to cut (zero_set_topology.h) and a saddle near an event
// only orients its cut (cut_axis.h).
//
// The paper's topology change of the level set f(., t) = 0 happens at a zero of V_k of
// saddle type: its Jacobian is non-singular and the real parts of its eigenvalues
// do not all share a sign (the paper's "index -1" rule is not right in 3-D: a sink has
// index -1 too). The kind is the number of expanding directions (eigenvalues with
// positive real part): 2 where two sheets meet and open a disc (sphere -> torus, two
// blobs merging), 1 where a neck pinches off (torus -> sphere, a blob splitting).
//
// FindSaddles, per step: in every grid cell where each component of V changes sign over
// the cell's 8 corners (the only cells whose trilinear V can vanish), Newton's method on
// the trilinear V from the cell centre (at most 5 steps, analytic Jacobian); a zero that
// lies inside the cell, is non-degenerate and of saddle type is kept. Zeros found from
// neighbouring cells (a zero on a shared face or node) are one.
//
// Non-degenerate means clearly hyperbolic: every eigenvalue's real part is at least
// kMinRate times the largest eigenvalue's modulus. Symmetric shapes give V whole rings of
// zeros (sphere -> torus: a circle of zeros in the torus's plane); the grid breaks such a
// ring into zeros of alternating kind whose rate along the ring is nearly 0 (at most 0.075
// of the largest in that case), while the zeros where the surface pinches have rates of
// comparable size (0.08 to 1 of the largest there).
#pragma once

#include "field.h"

#include <vector>

namespace eulermap {

struct Saddle {
  Point3 position;             // world coordinates
  int expandingDirections = 0; // 1 or 2
  // Where trajectories part: the saddle's stable manifold, to first order. Kind 2: the
  // direction of the stable line (the two sheets arrive along it); kind 1: the normal of
  // the stable plane (the pinching neck crosses it). Unit length.
  Point3 stable;
};

constexpr double kMinRate = 0.08;

// in:  V (one step's velocity field) on its grid
// out: the non-degenerate saddle-type zeros of the trilinear interpolant of V
std::vector<Saddle> FindSaddles(const VectorField &V);

// in:  a Jacobian J (row r = gradient of component r)
// out: the number of eigenvalues with positive real part when J is non-degenerate (every
//      real part at least kMinRate * the largest modulus away from 0), else -1. A saddle
//      has 1 or 2, a source 3, a sink 0.
int ExpandingDirections(const double J[3][3]);

} // namespace eulermap
