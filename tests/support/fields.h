// Test support: analytic fields on grids (the tests of saddle.h, cut_axis.h, surgery.h,
// grow_shrink.h and the topology of inside sets) and exact distances (closest.h, sdf.h).
#pragma once

#include "core/field.h"
#include "core/zero_set_topology.h"

#include <functional>

namespace eulermap::testing {

// f at every node of g.
ScalarField Sampled(const Grid &g, const std::function<double(const Point3 &)> &f);

// A 16^3-node grid over [-1, 1]^3 and V(x) = A (x - c) on its nodes (trilinear = exact).
VectorField LinearField(const double A[3][3], const Point3 &c);

// f(p) = sum_a curvature[a] (p - c)_a^2 on g: critical at c, f(c) = 0.
ScalarField Quadric(const Grid &g, const Point3 &c, const Point3 &curvature);

// Exact signed distance from p to an axis-aligned box's surface (negative inside).
double BoxSignedDistance(const Box3 &box, const Point3 &p);

// An event of `kind` at g's node `node`.
TopologyEvent EventAt(const Grid &g, const vcg::Point3i &node, TopologyEventKind kind);

} // namespace eulermap::testing
