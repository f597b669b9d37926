// Test support: analytic fields on grids (the tests of saddle.h, cut_axis.h, surgery.h,
// grow_shrink.h, inflate_shrink.h and the topology of inside sets) and exact distances (closest.h, sdf.h).
#pragma once

#include "core/field.h"
#include "core/zero_set_topology.h"

#include <functional>
#include <string>
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

// The signed distance to the twelve edges of the cube [-half, half]^3 as square bars of
// half-width `bar` (a cage of genus 5).
double CubeFrameDistance(const Point3 &p, double half, double bar);

// On 41^3 nodes 0.06 apart over [-1.2, 1.2]^3: f0 the distance to a ball of radius 1.1 about
// the origin, f1 to a cage (the twelve edges of the cube [-0.5, 0.5]^3 as bars 0.18 thick,
// genus 5) inside it: a source that must be hollowed out through the cage's six windows.
struct CageScene {
  CageScene();
  Grid g;
  ScalarField f0, f1;
};

// On 46^3 nodes 0.04 apart over [-0.9, 0.9]^3: f0 the distance to a ball of radius 0.75 about
// (0.1, 0.05, 0.1), f1 to a cup inside it (a cylinder of radius 0.4 from z = -0.5 to 0.5,
// hollowed to radius 0.32 above z = -0.42, open at the top).
struct CupScene {
  CupScene();
  Grid g;
  ScalarField f0, f1;
};

// On the CupScene's grid: f0 the distance to a ball of radius 0.78 about (0.05, 0.03, 0), f1
// to a vase inside it (a ball of radius 0.55 about (0, 0, -0.2), hollowed to 0.43, with a neck
// of radius 0.18 up to z = 0.85, bored to 0.09): a hollow reached through a narrow neck.
struct VaseScene {
  VaseScene();
  Grid g;
  ScalarField f0, f1;
};

// The frames k / frames (k = 0 .. frames) of `morph` whose inside set is not one component
// without cavities, as "t = ...: P parts, C cavities".
template <class Morph> std::vector<std::string> FramesNotOnePartWithoutCavities(const Morph &morph, int frames) {
  std::vector<std::string> wrong;
  ScalarField frame;
  for (int k = 0; k <= frames; ++k) {
    morph.Frame(double(k) / frames, frame);
    const ZeroSetTopology topology = Measure(frame);
    if (topology.components != 1 || topology.cavities != 0)
      wrong.push_back("t = " + std::to_string(double(k) / frames) + ": " + std::to_string(topology.components) + " parts, " +
                      std::to_string(topology.cavities) + " cavities");
  }
  return wrong;
}

// A 16^3-node grid over [-1, 1]^3 and V(x) = A (x - c) on its nodes (trilinear = exact).
VectorField LinearField(const double A[3][3], const Point3 &c);

// f(p) = sum_a curvature[a] (p - c)_a^2 on g: critical at c, f(c) = 0.
ScalarField Quadric(const Grid &g, const Point3 &c, const Point3 &curvature);

// Exact signed distance from p to an axis-aligned box's surface (negative inside).
double BoxSignedDistance(const Box3 &box, const Point3 &p);

// An event of `kind` at g's node `node`.
TopologyEvent EventAt(const Grid &g, const vcg::Point3i &node, TopologyEventKind kind);

} // namespace eulermap::testing
