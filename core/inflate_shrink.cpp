#include "inflate_shrink.h"
#include "grow_shrink.h"
#include "parallel.h"

#include <algorithm>
#include <limits>

namespace eulermap {

InflateShrink::InflateShrink(const ScalarField &f0, const ScalarField &f1) : f0_(f0), f1_(f1) {
  const Grid &g = f0.grid;
  const std::size_t count = f0.values.size();
  for (std::size_t n = 0; n < count; ++n)
    if (f1.values[n] < 0) l0_ = std::max(l0_, f0.values[n]);
  fb_.resize(count);
  const int nx = g.dims.X(), ny = g.dims.Y(), nz = g.dims.Z();
  ParallelFor(nz, [&](long z) {
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        const int toFace = std::min({x, y, int(z), nx - 1 - x, ny - 1 - y, nz - 1 - int(z)});
        const std::size_t n = g.Index(x, y, int(z));
        fb_[n] = std::max(f0.values[n] - l0_, (1.5 - toFace) * g.h);
      }
  });
  std::vector<char> inside(count), x1(count);
  for (std::size_t n = 0; n < count; ++n) inside[n] = fb_[n] < 0, x1[n] = f1.values[n] < 0;
  // The way out: -fB, the straight distance to B's surface, lengthened by what the path
  // around X1 (CarveDistance) adds beyond the 26-neighbour metric's error.
  wayOut_ = CarveDistance(g, inside, x1);
  for (std::size_t n = 0; n < count; ++n) {
    const double straight = -fb_[n], around = wayOut_[n];
    wayOut_[n] = straight + (inside[n] && around < std::numeric_limits<double>::infinity()
                                 ? std::max(0.0, around - (1 + kChamferError) * straight - 2 * g.h)
                                 : 0.0);
    if (inside[n]) l1_ = std::max(l1_, f1.values[n]);
  }
  switch_ = l0_ + l1_ > 0 ? l0_ / (l0_ + l1_) : 0.5;
}

void InflateShrink::Frame(double t, ScalarField &out) const {
  out.grid = f0_.grid;
  if (t <= 0 || t >= 1) {  // f0 and f1 exactly
    out.values = t <= 0 ? f0_.values : f1_.values;
    return;
  }
  out.values.resize(f0_.values.size());
  const bool inflate = t <= switch_;
  const double s = inflate ? (switch_ > 0 ? t / switch_ : 1) : (switch_ < 1 ? (t - switch_) / (1 - switch_) : 1);
  ParallelFor(long(out.values.size()), [&](long n) {
    out.values[n] = inflate ? (1 - s) * f0_.values[n] + s * fb_[n] : s * f1_.values[n] - (1 - s) * wayOut_[n];
  });
}

} // namespace eulermap
