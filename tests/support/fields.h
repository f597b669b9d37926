// Test support: analytic fields on grids (the tests of saddle.h, cut_axis.h, surgery.h,
// grow_shrink.h, inflate_shrink.h and the topology of inside sets) and exact distances (closest.h, sdf.h).
#pragma once

#include "core/field.h"
#include "core/zero_set_topology.h"

#include <functional>
#include <vector>

namespace eulermap::testing {

// f at every node of g.
ScalarField Sampled(const Grid &g, const std::function<double(const Point3 &)> &f);

// The signed distance to a ball's surface (negative inside).
std::function<double(const Point3 &)> Ball(const Point3 &c, double r);

// Per node, whether f < 0 there (its inside set).
std::vector<char> Inside(const ScalarField &f);

// On 41 x 25 x 25 nodes 0.1 apart over [-2, 2] x [-1.2, 1.2]^2: f0 the distance to a ball of
// radius 0.6 at x = -1.1, f1 to the union of balls at x = xa (radius ra) and x = xb (rb),
// on the x axis (the morphs' tests: target parts the source does or does not touch).
struct BallScene {
  BallScene(double xa, double ra, double xb, double rb);
  Grid g;
  ScalarField f0, f1;
};

// A 16^3-node grid over [-1, 1]^3 and V(x) = A (x - c) on its nodes (trilinear = exact).
VectorField LinearField(const double A[3][3], const Point3 &c);

// f(p) = sum_a curvature[a] (p - c)_a^2 on g: critical at c, f(c) = 0.
ScalarField Quadric(const Grid &g, const Point3 &c, const Point3 &curvature);

// Exact signed distance from p to an axis-aligned box's surface (negative inside).
double BoxSignedDistance(const Box3 &box, const Point3 &p);

// An event of `kind` at g's node `node`.
TopologyEvent EventAt(const Grid &g, const vcg::Point3i &node, TopologyEventKind kind);

} // namespace eulermap::testing
