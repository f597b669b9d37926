// Test support: random points and a comparison of points that prints both.
#pragma once

#include "core/mesh.h"

#include <random>
#include <vector>

#define EXPECT_POINT_NEAR(p, q, tol)                                                                              \
  EXPECT_LE(vcg::Distance((p), (q)), (tol)) << "(" << (p).X() << "," << (p).Y() << "," << (p).Z() << ") vs (" \
                                            << (q).X() << "," << (q).Y() << "," << (q).Z() << ")"

namespace eulermap::testing {

// n points uniform in [-radius, radius]^3, the same for the same seed.
inline std::vector<Point3> RandomPoints(int n, unsigned seed, double radius = 1) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-radius, radius);
  std::vector<Point3> pts(n);
  for (auto &p : pts) p = Point3(u(gen), u(gen), u(gen));
  return pts;
}

} // namespace eulermap::testing
