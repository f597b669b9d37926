// eulermap::Tracker — the integral formula (Eq. 7) for any set of points.
//
// Each tracked point p carries the level value c it started on, c = f(p0, 0) (0 for
// points on the source surface; points off it follow their own level set, Fig. 7).
// One step k -> k+1:
//   advect:    p <- p + dt V_k(p)  (Eq. 7; evaluated at the midpoint p + dt/2 V_k(p),
//              a second-order variant of the same formula with the same field V_k)
//   pull back: Newton steps p <- p - (f(p, t_k+1) - c) grad f / |grad f|^2, each at most
//              one grid cell long, until |f - c| < 1e-4 cells (at most 8 steps).
// Trajectories depend on the fields alone (the map is Eulerian): points are independent,
// and the step runs over them in parallel.
#pragma once

#include "field.h"

#include <vector>

namespace eulermap {

class Tracker {
 public:
  // in: starting points p0 and the frame f(., 0) that gives their level values
  Tracker(std::vector<Point3> points, const ScalarField &f0);

  // Moves every point by one step through V (= V_k) onto its level set of fNext = f(., t_k+1).
  void Advance(const VectorField &V, const ScalarField &fNext, double dt);

  const std::vector<Point3> &Points() const { return points_; }
  const std::vector<double> &Levels() const { return levels_; }

 private:
  std::vector<Point3> points_;
  std::vector<double> levels_;
};

// Moves p onto the level set f = level (the pull-back above); returns the new point.
Point3 PullBack(const ScalarField &f, Point3 p, double level);

} // namespace eulermap
