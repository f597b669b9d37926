#include "tracker.h"

#include <cmath>

namespace eulermap {

Tracker::Tracker(std::vector<Point3> points, const ScalarField &f0) : points_(std::move(points)), levels_(points_.size()) {
  for (std::size_t n = 0; n < points_.size(); ++n) levels_[n] = f0.Value(points_[n]);
}

Point3 PullBack(const ScalarField &f, Point3 p, double level) {
  const double h = f.grid.h;
  for (int it = 0; it < 8; ++it) {
    const double e = f.Value(p) - level;
    if (std::abs(e) < 1e-4 * h) break;
    const Point3 g = f.Gradient(p);
    const double g2 = g.SquaredNorm();
    if (g2 < 1e-12) break;
    Point3 step = g * (e / g2);
    const double len = step.Norm();
    if (len > h) step *= h / len;
    p -= step;
  }
  return p;
}

void Tracker::Advance(const VectorField &V, const ScalarField &fNext, double dt) {
#pragma omp parallel for schedule(static)
  for (long n = 0; n < long(points_.size()); ++n) {
    Point3 &p = points_[n];
    const Point3 mid = p + V.Sample(p) * (dt / 2);  // Eq. 7, midpoint rule
    p = PullBack(fNext, p + V.Sample(mid) * dt, levels_[n]);
  }
}

} // namespace eulermap
