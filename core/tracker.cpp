#include "tracker.h"
#include "parallel.h"

#include <cmath>

namespace eulermap {

Tracker::Tracker(std::vector<Point3> points, std::vector<double> levels)
    : points_(std::move(points)), levels_(std::move(levels)) {}

namespace {

// The pull-back of tracker.h: value(q) = f(q), gradient(q) = grad f(q), always asked at the
// point value was last asked at; h: the grid cell.
template <class Value, class Gradient> Point3 PullBackOn(Value value, Gradient gradient, double h, Point3 p, double level) {
  for (int it = 0; it < 8; ++it) {
    const double e = value(p) - level;
    if (std::abs(e) < 1e-4 * h) break;
    const Point3 g = gradient(p);
    const double g2 = g.SquaredNorm();
    if (g2 < 1e-12) break;
    Point3 step = g * (e / g2);
    const double len = step.Norm();
    if (len > h) step *= h / len;
    p -= step;
  }
  return p;
}

} // namespace

Point3 PullBack(const ScalarField &f, Point3 p, double level) {
  // The gradient only when the point is not there yet: most points of a step are after one
  // Newton step.
  return PullBackOn([&](const Point3 &q) { return f.Value(q); }, [&](const Point3 &q) { return f.Gradient(q); },
                    f.grid.h, p, level);
}

Point3 PullBack(const HermiteField &f, Point3 p, double level) {
  Point3 g;  // the gradient comes with the value, from one evaluation of the polynomial
  return PullBackOn([&](const Point3 &q) { return f.Value(q, &g); }, [&](const Point3 &) { return g; }, f.grid().h,
                    p, level);
}

std::size_t Tracker::Add(const std::vector<Point3> &points, double level) {
  const std::size_t first = points_.size();
  points_.insert(points_.end(), points.begin(), points.end());
  levels_.resize(points_.size(), level);
  return first;
}

void Tracker::Advance(const VectorField &V, const ScalarField &fNext, double dt) {
  ParallelFor(long(points_.size()), [&](long n) {
    Point3 &p = points_[n];
    const Point3 mid = p + V.Sample(p) * (dt / 2);  // Eq. 7, midpoint rule
    p = PullBack(fNext, p + V.Sample(mid) * dt, levels_[n]);
  });
}

void Tracker::Settle(const HermiteField &f1) {
  ParallelFor(long(points_.size()), [&](long n) { points_[n] = PullBack(f1, points_[n], levels_[n]); });
}

} // namespace eulermap
