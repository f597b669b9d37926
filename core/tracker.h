// eulermap::Tracker — the integral formula (Eq. 7) for any set of points.
//
// Each tracked point p carries the level value c it started on: 0 for points on the source
// surface (its vertices, points on its faces), c = f(p0, 0) for points off it, which follow
// their own level set (Fig. 7; DESIGN.md).
// One step k -> k+1:
//   advect:    p <- p + dt V_k(p)  (Eq. 7; evaluated at the midpoint p + dt/2 V_k(p),
//              a second-order variant of the same formula with the same field V_k)
//   pull back: Newton steps p <- p - (f(p, t_k+1) - c) grad f / |grad f|^2, each at most
//              one grid cell long, until |f - c| < 1e-4 cells (at most 8 steps).
// The last frame, f1, is read once more with sub-cell accuracy (hermite_field.h): after
// the last step every point is pulled back onto its level of f1's HermiteField (Settle).
// The frames in between are read trilinearly.
// Trajectories depend on the fields alone (the map is Eulerian): points are independent,
// and the step runs over them in parallel.
#pragma once

#include "field.h"
#include "hermite_field.h"

#include <vector>

namespace eulermap {

class Tracker {
 public:
  // in: starting points p0 and the level c of each (0 for a point on the surface)
  Tracker(std::vector<Point3> points, std::vector<double> levels);

  // Moves every point by one step through V (= V_k) onto its level set of fNext = f(., t_k+1).
  void Advance(const VectorField &V, const ScalarField &fNext, double dt);
  // After the last step: every point pulled back onto its level set of f1 read as a
  // HermiteField.
  void Settle(const HermiteField &f1);

  // Appends points (each on its level) to be tracked from now on; returns the index of the first.
  std::size_t Add(const std::vector<Point3> &points, double level);

  const std::vector<Point3> &Points() const { return points_; }
  const std::vector<double> &Levels() const { return levels_; }

 private:
  std::vector<Point3> points_;
  std::vector<double> levels_;
};

// Moves p onto the level set f = level (the pull-back above); returns the new point.
Point3 PullBack(const ScalarField &f, Point3 p, double level);
Point3 PullBack(const HermiteField &f, Point3 p, double level);

} // namespace eulermap
