#include "distance_transform.h"

#include <type_traits>

#include "parallel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace eulermap {

namespace {

struct Triangle {
  Point3 a, b, c;
};

// p minus its nearest point on triangle t: the nearest point by the Voronoi regions of the
// triangle's corners, edges and face (barycentric tests on the projections of p). Not
// vcglib's: vcg::TrianglePointDistance (exact, but a normalised plane, a projection and
// three segment distances per call) made this SDF about three times slower (docs/NOTES.md);
// face::PointDistanceBase needs face normals and its
// 1e-6 tolerances put it off by up to 1e-3 cells (test_sdf).
Point3 Offset(const Triangle &t, const Point3 &p) {
  const Point3 ab = t.b - t.a, ac = t.c - t.a, ap = p - t.a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap;  // corner a
  const Point3 bp = p - t.b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp;  // corner b
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return ap - ab * (d1 / (d1 - d3));  // edge ab
  const Point3 cp = p - t.c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp;  // corner c
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return ap - ac * (d2 / (d2 - d6));  // edge ac
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {  // edge bc
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return bp - (t.c - t.b) * w;
  }
  const double denom = 1 / (va + vb + vc);  // inside the face
  const double v = vb * denom, w = vc * denom;
  return ap - ab * v - ac * w;
}

double SquaredDistance(const Triangle &t, const Point3 &p) { return Offset(t, p).SquaredNorm(); }

template <class Gradient>
ScalarField Distance(const Mesh &mesh, const Grid &grid, Gradient *gradient, const Interrupt &interrupt) {
  using Vector = typename std::decay_t<decltype(gradient->values)>::value_type;
  std::vector<Triangle> tris;
  for (const Face &f : mesh.face)
    if (!f.IsD()) tris.push_back({f.cP(0), f.cP(1), f.cP(2)});
  ScalarField out(grid, 0.0);
  if (gradient) *gradient = Gradient(grid, Vector(0, 0, 0));
  if (tris.empty()) return out;
  const std::size_t count = grid.NodeCount();
  std::vector<double> d2(count, std::numeric_limits<double>::infinity());
  std::vector<int> nearest(count, -1);
  if (interrupt.Stop()) return out;  // the arrays are touched as they are filled: seconds on big grids
  const vcg::Point3i &dims = grid.dims;

  // 1. Seed: each face, the nodes within one cell of its box. A face less than a cell tall
  //    reaches the z-layers slab - 1 .. slab + 2 of the slab of its lowest corner, so faces
  //    of slabs 4 apart never write the same node and run in parallel; taller faces after.
  std::vector<std::vector<int>> bySlab(dims.Z());
  std::vector<int> tall;
  for (int t = 0; t < int(tris.size()); ++t) {
    const double zmin = std::min({tris[t].a.Z(), tris[t].b.Z(), tris[t].c.Z()});
    const double zmax = std::max({tris[t].a.Z(), tris[t].b.Z(), tris[t].c.Z()});
    if (zmax - zmin >= grid.h)
      tall.push_back(t);
    else
      bySlab[std::clamp(int((zmin - grid.origin.Z()) / grid.h), 0, dims.Z() - 1)].push_back(t);
  }
  auto seed = [&](int t) {
    Box3 box;
    box.Add(tris[t].a), box.Add(tris[t].b), box.Add(tris[t].c);
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::max(0, int(std::ceil((box.min[a] - grid.origin[a]) / grid.h - 1)));
      hi[a] = std::min(dims[a] - 1, int(std::floor((box.max[a] - grid.origin[a]) / grid.h + 1)));
    }
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int i = lo[0]; i <= hi[0]; ++i) {
          const std::size_t n = grid.Index(i, j, k);
          const double s = SquaredDistance(tris[t], grid.Node(i, j, k));
          if (s < d2[n]) d2[n] = s, nearest[n] = t;
        }
  };
  for (int phase = 0; phase < 4; ++phase) {
    ParallelFor((dims.Z() - phase + 3) / 4, [&](long n) {  // slabs phase, phase + 4, ...
      for (int t : bySlab[phase + 4 * n]) seed(t);
    });
    if (interrupt.Stop()) return out;
  }
  for (int t : tall) seed(t);

  // 2. Propagate: eight sweeps, one per octant direction (sx, sy, sz), each visiting the
  //    nodes in that order; a node tests the nearest faces of its three neighbours behind
  //    it. A sweep depends on its own updates, so it runs on one thread.
  const long stride[3] = {1, long(dims.X()), long(dims.X()) * dims.Y()};
  std::size_t sincePoll = 0;  // nodes swept since the interrupt was asked
  for (int octant = 0; octant < 8; ++octant) {
    const int dir[3] = {octant & 1 ? -1 : 1, octant & 2 ? -1 : 1, octant & 4 ? -1 : 1};
    int c[3];
    for (c[2] = dir[2] > 0 ? 0 : dims[2] - 1; c[2] >= 0 && c[2] < dims[2]; c[2] += dir[2]) {
      if ((sincePoll += std::size_t(stride[2])) > kNodesBetweenPolls) {
        sincePoll = std::size_t(stride[2]);
        if (interrupt.Stop()) return out;
      }
      for (c[1] = dir[1] > 0 ? 0 : dims[1] - 1; c[1] >= 0 && c[1] < dims[1]; c[1] += dir[1])
        for (c[0] = dir[0] > 0 ? 0 : dims[0] - 1; c[0] >= 0 && c[0] < dims[0]; c[0] += dir[0]) {
          const long n = long(grid.Index(c[0], c[1], c[2]));
          for (int a = 0; a < 3; ++a) {
            const int behind = c[a] - dir[a];
            if (behind < 0 || behind >= dims[a]) continue;
            const int t = nearest[n - dir[a] * stride[a]];
            if (t < 0 || t == nearest[n]) continue;
            const double q = SquaredDistance(tris[t], grid.Node(c[0], c[1], c[2]));
            if (q < d2[n]) d2[n] = q, nearest[n] = t;
          }
        }
    }
  }
  ParallelFor(long(count), [&](long n) { out.values[n] = std::sqrt(d2[n]); });
  if (gradient) {
    ParallelFor(long(count), [&](long n) {
      const long i = n % dims.X(), j = n / dims.X() % dims.Y(), k = n / (long(dims.X()) * dims.Y());
      const Triangle &t = tris[nearest[n]];
      const Point3 away = Offset(t, grid.Node(i, j, k));
      const double d = away.Norm();
      const Point3 unit = d > 0 ? away / d : ((t.b - t.a) ^ (t.c - t.a)).Normalize();  // on the face: its normal
      gradient->values[n] = Vector(unit[0], unit[1], unit[2]);
    });
  }
  return out;
}

} // namespace

ScalarField UnsignedDistance(const Mesh &mesh, const Grid &grid, VectorField *gradient, const Interrupt &interrupt) {
  return Distance(mesh, grid, gradient, interrupt);
}

ScalarField UnsignedDistance(const Mesh &mesh, const Grid &grid, GradientField *gradient, const Interrupt &interrupt) {
  return Distance(mesh, grid, gradient, interrupt);
}

} // namespace eulermap
