// Signed distance fields on grid nodes, with the inside decided by the generalized
// winding number (DESIGN.md: sdf.h).
//
// References
//   [J13] A. Jacobson, L. Kavan, O. Sorkine-Hornung, "Robust inside-outside segmentation
//         using generalized winding numbers", ACM TOG 32(4), 2013.
//   [VS83] A. Van Oosterom, J. Strackee, "The solid angle of a plane triangle",
//         IEEE Trans. Biomed. Eng. 30(2), 1983.
//   [B18] G. Barill, N. Dickson, R. Schmidt, D. I. W. Levin, A. Jacobson, "Fast winding
//         numbers for soups and clouds", ACM TOG 37(4), 2018.
//
// The winding number w(p) = (1/4pi) sum_t Omega_t(p) [J13], with Omega_t the signed solid
// angle of triangle t seen from p [VS83]. It is 1 inside and 0 outside a closed,
// outward-oriented surface and degrades gracefully across holes (camelhead's open neck),
// so thresholding it at 1/2 gives an inside for open meshes too [J13].
//
// [B18] evaluates the sum over a bounding-volume tree: the triangles of a node seen from
// far away are replaced by the Taylor series of the dipole kernel g(y) = y / |y|^3 about
// their area-weighted centroid c. With y = c - p, r = |y|, a_t n_t the area-weighted
// normal of triangle t and d = x - c for x on it,
//   4pi w_node(p) ~ y.N / r^3                                                (order 1)
//                 + tr(M) / r^3 - 3 y.(M y) / r^5                            (order 2)
//                 + 15/2 T[y,y,y] / r^7 - 3/2 (2u + v).y / r^5               (order 3)
//   N = sum_t a_t n_t,  M = sum_t a_t d_t n_t^T (d_t at the triangle's centroid),
//   T_ijk = sum_t n_ti int_t d_j d_k dA,  u_k = sum_i T_iik,  v_i = sum_j T_ijj,
// all exact integrals over the flat triangles. The expansion is used when r > beta * rho,
// rho being the node's radius about c; nearer leaves are summed exactly.
// [B18] suggests beta = 2. Measured against the exact sum at points in and around
// bunny.off / camelhead.off (down to 1% of the diagonal from the surface), the largest
// error was 3.8e-3 / 6.2e-3 with beta = 2 and 6.3e-4 / 9.6e-4 with beta = 3 (order 2
// alone: 1.4e-2 at beta = 3); beta = 3 costs ~1.5-2x the evaluations of beta = 2.
// SignedDistance needs only the sign of w - 1/2 (Inside: beta = 2 unless w is near 1/2),
// but the numbers are also meant to be read.
#include "sdf.h"

#include "distance_transform.h"
#include "parallel.h"

#include <vcg/space/distance3.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <unordered_map>
#include <vector>

namespace eulermap {

namespace {

constexpr double kBeta = 3.0;        // far-field acceptance: |c - p| > kBeta * radius (see above)
constexpr double kBetaSign = 2.0;     // enough to tell w from 1/2 (measured error <= 6.2e-3) ...
constexpr double kSignMargin = 0.05;  // ... outside [1/2 - margin, 1/2 + margin]
constexpr int kLeafSize = 8;    // triangles per leaf of the tree
constexpr double kFourPi = 4 * M_PI;

// Signed solid angle of triangle (a, b, c) seen from p, by the Van Oosterom–Strackee
// formula [VS83]: tan(Omega/2) = det[A B C] / (|A||B||C| + (A.B)|C| + (B.C)|A| + (C.A)|B|),
// A = a - p etc. atan2 keeps the right branch for |Omega| > pi.
//   in:  triangle corners a, b, c (counter-clockwise seen from the side the normal
//        (b-a)x(c-a) points to); query point p
//   out: Omega in [-2pi, 2pi], positive when p is behind the triangle (on the side
//        opposite its normal); 0 for p on the triangle's plane.
inline double SolidAngle(const Point3 &a, const Point3 &b, const Point3 &c, const Point3 &p) {
  const Point3 A = a - p, B = b - p, C = c - p;
  const double la = A.Norm(), lb = B.Norm(), lc = C.Norm();
  const double det = A.dot(B ^ C);
  const double den = la * lb * lc + A.dot(B) * lc + B.dot(C) * la + C.dot(A) * lb;
  return 2 * std::atan2(det, den);
}

// The live faces' corners, 3 per face.
std::vector<Point3> LiveCorners(const Mesh &mesh) {
  std::vector<Point3> corners;
  corners.reserve(3 * std::size_t(mesh.fn));
  for (const Face &f : mesh.face)
    if (!f.IsD())
      for (int v = 0; v < 3; ++v) corners.push_back(f.cP(v));
  return corners;
}

} // namespace

// A bounding-volume tree over the triangles, built by median splits of the triangle
// centroids along the longest axis of their box. Nodes are stored depth-first: a node's
// left child follows it, `right` indexes the right child (-1 for a leaf).
struct WindingNumber::Tree {
  struct Node {
    Point3 centre;       // area-weighted centroid c of the node's triangles
    double radius2 = 0;  // squared radius about c: the expansion is used beyond beta^2 radius2
    Point3 normal;       // order 1: N = sum_t a_t n_t
    double m[9] = {};    // order 2: M = sum_t a_t (x_t - c) n_t^T, row-major
    double traceM = 0;
    double t[18] = {};   // order 3: T_i = sum_t n_ti Q_t, i = 0..2, each symmetric (xx xy xz yy yz zz)
    Point3 tContracted;  // order 3: 2 u + v, u_k = sum_i (T_i)_ik, v_i = trace(T_i)
    int first = 0, count = 0;  // the node's triangles: corners[3*first .. 3*(first+count))
    int right = -1;
  };
  std::vector<Point3> corners;  // 3 per triangle, in tree order
  std::vector<Node> nodes;

  // in:  triangle corners (3 per triangle)
  // out: the tree; corners reordered so that every node's triangles are contiguous.
  explicit Tree(std::vector<Point3> tris) {
    const int n = int(tris.size() / 3);
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::vector<Point3> centroid(n);
    for (int t = 0; t < n; ++t) centroid[t] = (tris[3 * t] + tris[3 * t + 1] + tris[3 * t + 2]) / 3.0;
    if (n > 0) {
      nodes.reserve(2 * (n / kLeafSize + 1));
      Build(order, centroid, 0, n);
    }
    corners.resize(tris.size());
    for (int t = 0; t < n; ++t)
      for (int v = 0; v < 3; ++v) corners[3 * t + v] = tris[3 * order[t] + v];
    for (Node &node : nodes) Summarize(node);
  }

  // Splits order[begin, end) recursively; returns the index of the node made for it.
  int Build(std::vector<int> &order, const std::vector<Point3> &centroid, int begin, int end) {
    const int id = int(nodes.size());
    nodes.emplace_back();
    nodes[id].first = begin;
    nodes[id].count = end - begin;
    if (end - begin <= kLeafSize) return id;
    Box3 box;
    for (int t = begin; t < end; ++t) box.Add(centroid[order[t]]);
    const Point3 dim = box.Dim();
    const int axis = dim[0] >= dim[1] ? (dim[0] >= dim[2] ? 0 : 2) : (dim[1] >= dim[2] ? 1 : 2);
    const int mid = begin + (end - begin) / 2;
    std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                     [&](int a, int b) { return centroid[a][axis] < centroid[b][axis]; });
    Build(order, centroid, begin, mid);
    const int right = Build(order, centroid, mid, end);
    nodes[id].right = right;
    return id;
  }

  // Fills the node's expansion data (header comment) from its triangles (in tree order).
  void Summarize(Node &node) const {
    const Point3 *tri = corners.data() + 3 * node.first;
    double area = 0;
    Point3 centre(0, 0, 0), normal(0, 0, 0);
    Box3 box;
    for (int t = 0; t < node.count; ++t) {
      const Point3 &a = tri[3 * t], &b = tri[3 * t + 1], &c = tri[3 * t + 2];
      const Point3 an = ((b - a) ^ (c - a)) * 0.5;  // a_t n_t
      const double at = an.Norm();
      area += at;
      centre += (a + b + c) * (at / 3.0);
      normal += an;
      box.Add(a);
      box.Add(b);
      box.Add(c);
    }
    centre = area > 0 ? centre / area : box.Center();  // all-degenerate: any point will do
    double r2 = 0;
    double m[9] = {}, t3[18] = {};
    for (int t = 0; t < node.count; ++t) {
      const Point3 &a = tri[3 * t], &b = tri[3 * t + 1], &c = tri[3 * t + 2];
      const Point3 an = ((b - a) ^ (c - a)) * 0.5;
      const Point3 pa = a - centre, pb = b - centre, pc = c - centre, s = pa + pb + pc;
      const Point3 d = s / 3.0;  // x_t - c
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m[3 * i + j] += d[i] * an[j];
      // Q_t = int_t (x - c)(x - c)^T dA = a_t/12 (sum_v p_v p_v^T + s s^T), p_v = corner - c,
      // s = sum_v p_v; so n_ti Q_t = an_i/12 (...).
      static const int J[6] = {0, 0, 0, 1, 1, 2}, K[6] = {0, 1, 2, 1, 2, 2};
      for (int e = 0; e < 6; ++e) {
        const int j = J[e], k = K[e];
        const double q = (pa[j] * pa[k] + pb[j] * pb[k] + pc[j] * pc[k] + s[j] * s[k]) / 12;
        for (int i = 0; i < 3; ++i) t3[6 * i + e] += an[i] * q;
      }
      r2 = std::max({r2, pa.SquaredNorm(), pb.SquaredNorm(), pc.SquaredNorm()});
    }
    node.centre = centre;
    node.normal = normal;
    node.radius2 = r2;
    std::copy(m, m + 9, node.m);
    node.traceM = m[0] + m[4] + m[8];
    std::copy(t3, t3 + 18, node.t);
    // u_k = sum_i (T_i)_ik, v_i = trace(T_i); entry (i, k) of a packed symmetric matrix:
    static const int P[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};
    for (int k = 0; k < 3; ++k) {
      double u = 0;
      for (int i = 0; i < 3; ++i) u += t3[6 * i + P[i][k]];
      const double v = t3[6 * k + 0] + t3[6 * k + 3] + t3[6 * k + 5];
      node.tContracted[k] = 2 * u + v;
    }
  }

  // in:  query point p; beta — the far-field acceptance ratio
  // out: 4pi * w(p): the sum of exact solid angles of near leaves and the third-order
  //      expansion of far nodes [B18].
  double SolidAngleSum(const Point3 &p, double beta) const {
    const double beta2 = beta * beta;
    if (nodes.empty()) return 0;
    int stack[128];  // median splits: depth <= log2(#triangles) + 1
    int top = 0;
    stack[top++] = 0;
    double sum = 0;
    while (top > 0) {
      const Node &node = nodes[stack[--top]];
      const Point3 y = node.centre - p;
      const double r2 = y.SquaredNorm();
      if (r2 > beta2 * node.radius2) {
        const double r = std::sqrt(r2), inv3 = 1 / (r2 * r), inv5 = inv3 / r2, inv7 = inv5 / r2;
        const double *m = node.m;
        const double yMy = y[0] * (m[0] * y[0] + m[1] * y[1] + m[2] * y[2]) +
                           y[1] * (m[3] * y[0] + m[4] * y[1] + m[5] * y[2]) +
                           y[2] * (m[6] * y[0] + m[7] * y[1] + m[8] * y[2]);
        double yTy = 0;  // T[y, y, y] = sum_i y_i y^T T_i y
        for (int i = 0; i < 3; ++i) {
          const double *t = node.t + 6 * i;
          yTy += y[i] * (t[0] * y[0] * y[0] + t[3] * y[1] * y[1] + t[5] * y[2] * y[2] +
                         2 * (t[1] * y[0] * y[1] + t[2] * y[0] * y[2] + t[4] * y[1] * y[2]));
        }
        // 4pi times the order-1, -2 and -3 terms of the expansion (header comment).
        sum += y.dot(node.normal) * inv3                            // order 1
               + node.traceM * inv3 - 3 * yMy * inv5                // order 2
               + 7.5 * yTy * inv7 - 1.5 * y.dot(node.tContracted) * inv5;  // order 3
      } else if (node.right < 0) {
        const Point3 *tri = corners.data() + 3 * node.first;
        for (int t = 0; t < node.count; ++t) sum += SolidAngle(tri[3 * t], tri[3 * t + 1], tri[3 * t + 2], p);
      } else {
        stack[top++] = node.right;
        stack[top++] = int(&node - nodes.data()) + 1;
      }
    }
    return sum;
  }
};

// in:  mesh — triangle mesh (any orientation convention: outward normals give w ~ 1
//      inside); deleted faces are skipped. The mesh is copied, so it may change or go
//      away afterwards.
// out: the tree for hierarchical evaluation.
WindingNumber::WindingNumber(const Mesh &mesh) : WindingNumber(LiveCorners(mesh)) {}

// in:  corners — 3 per triangle (any number of triangles, none: w = 0 everywhere)
WindingNumber::WindingNumber(std::vector<Point3> corners) : tree_(std::make_unique<Tree>(std::move(corners))) {}

WindingNumber::~WindingNumber() = default;

// in:  p — query point (thread-safe: reads the tree only)
// out: the generalized winding number w(p) [J13]: ~1 inside, ~0 outside a closed outward-
//      oriented mesh; far nodes are approximated [B18] (absolute error below ~1e-3).
double WindingNumber::operator()(const Point3 &p) const { return tree_->SolidAngleSum(p, kBeta) / kFourPi; }

// in:  p — query point
// out: w(p) from a cheaper evaluation (beta = 2, error <= 6.2e-3 measured)
double WindingNumber::Estimate(const Point3 &p) const { return tree_->SolidAngleSum(p, kBetaSign) / kFourPi; }

// in:  p — query point; w — w(p) within the estimate's error (Estimate, or sums of such)
// out: whether w(p) >= 1/2: w decides unless it lies within kSignMargin of 1/2, where the
//      accurate evaluation does.
bool WindingNumber::Inside(const Point3 &p, double w) const {
  if (std::abs(w - 0.5) > kSignMargin) return w > 0.5;
  return (*this)(p) >= 0.5;
}

namespace {

// The cone that closes the mesh: its boundary chain (the edges used more often in one
// direction than in the other) joined to an apex, the mean of the chain's vertices, each
// triangle oriented against its edge. Then mesh + cone is a closed surface (a 2-cycle: every
// edge used as often in one direction as in the other; the apex's edges cancel as the
// chain is a cycle), so its winding number w_mesh + w_cone is a whole number, constant on
// each connected piece of space minus both. Returns 3 corners per triangle; none for a
// closed mesh.
std::vector<Point3> ClosingCone(const Mesh &mesh) {
  std::unordered_map<std::uint64_t, int> balance;  // per undirected edge: uses a->b minus b->a (a < b)
  for (const Face &f : mesh.face) {
    if (f.IsD()) continue;
    for (int e = 0; e < 3; ++e) {
      const std::uint64_t a = vcg::tri::Index(mesh, f.cV(e)), b = vcg::tri::Index(mesh, f.cV((e + 1) % 3));
      balance[a < b ? (a << 32 | b) : (b << 32 | a)] += a < b ? 1 : -1;
    }
  }
  std::vector<std::pair<std::size_t, std::size_t>> chain;  // directed boundary edges, with repeats
  for (const auto &[edge, k] : balance)
    for (int n = 0; n < std::abs(k); ++n) {
      const std::size_t a = edge >> 32, b = edge & 0xffffffffu;
      chain.push_back(k > 0 ? std::make_pair(a, b) : std::make_pair(b, a));
    }
  std::sort(chain.begin(), chain.end());  // an order independent of the hash table's
  Point3 apex(0, 0, 0);
  for (const auto &[a, b] : chain) apex += mesh.vert[a].cP() + mesh.vert[b].cP();
  std::vector<Point3> cone;
  if (chain.empty()) return cone;
  apex /= 2.0 * chain.size();
  for (const auto &[a, b] : chain) cone.insert(cone.end(), {apex, mesh.vert[b].cP(), mesh.vert[a].cP()});
  return cone;
}

// in:  the unsigned distance d at every node, the mesh's winding number, the cone closing the
//      mesh (ClosingCone)
// out: per node, whether it lies inside (winding number >= 1/2)
// W = w_mesh + w_cone is a whole number, constant along a grid edge that crosses neither the
// mesh nor the cone. An edge (m, n) with d(m) + d(n) > h crosses no face (a crossing point x
// would give d(m) + d(n) <= |m - x| + |x - n| = h), and one whose ends both lie farther than h
// from every cone triangle crosses none of them. The winding number itself is evaluated at
// the nodes with an edge that may cross the mesh and at those near the cone (camelhead in
// Table 1 row 1: 3.8% of the nodes, against all of them); W is flooded from them across the
// other edges, and elsewhere w_mesh = W - w_cone (the cone's few triangles are cheap).
// The interrupt is asked every kNodesBetweenPolls nodes of each pass; once it says stop, the
// passes skip their work and the result means nothing (the caller returns).
std::vector<char> Inside(const ScalarField &d, const WindingNumber &winding, const std::vector<Point3> &cone,
                         const Interrupt &interrupt) {
  const Grid &grid = d.grid;
  const std::size_t count = grid.NodeCount();
  const vcg::Point3i &dims = grid.dims;
  const long stride[3] = {1, long(dims.X()), long(dims.X()) * dims.Y()};
  const double h = grid.h * (1 + 1e-9);
  auto node = [&](long n) { return grid.Node(int(n % dims.X()), int(n / dims.X() % dims.Y()), int(n / stride[2])); };
  auto forEachNeighbour = [&](long n, auto &&fn) {
    const int c[3] = {int(n % dims.X()), int(n / dims.X() % dims.Y()), int(n / stride[2])};
    for (int a = 0; a < 3; ++a) {
      if (c[a] > 0) fn(n - stride[a]);
      if (c[a] + 1 < dims[a]) fn(n + stride[a]);
    }
  };
  const WindingNumber coneWinding(cone);
  std::vector<char> nearCone(count, 0);  // within h of a cone triangle
  for (std::size_t t = 0; t < cone.size(); t += 3) {
    const vcg::Triangle3<double> tri(cone[t], cone[t + 1], cone[t + 2]);
    Box3 box;
    for (int v = 0; v < 3; ++v) box.Add(cone[t + v]);
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::max(0, int(std::floor((box.min[a] - h - grid.origin[a]) / grid.h)));
      hi[a] = std::min(dims[a] - 1, int(std::ceil((box.max[a] + h - grid.origin[a]) / grid.h)));
    }
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int i = lo[0]; i <= hi[0]; ++i) {
          double distance;
          Point3 closest;
          vcg::TrianglePointDistance(tri, grid.Node(i, j, k), distance, closest);
          if (distance <= h) nearCone[grid.Index(i, j, k)] = 1;
        }
  }
  auto crossesNothing = [&](long m, long n) { return d.values[m] + d.values[n] > h && !nearCone[m] && !nearCone[n]; };

  constexpr long kUnknown = std::numeric_limits<long>::min();
  std::vector<long> whole(count, kUnknown);  // W
  std::vector<char> inside(count);
  auto evaluate = [&](long n) {
    const Point3 p = node(n);
    const double w = winding.Estimate(p);
    whole[n] = std::lround(w + coneWinding(p));
    inside[n] = winding.Inside(p, w);
  };
  auto stop = [&](long n) { return (n & long(kNodesBetweenPolls - 1)) == 0 ? interrupt.Stop() : interrupt.Cancelled(); };
  ParallelFor(long(count), [&](long n) {
    if (stop(n)) return;
    bool near = nearCone[n];
    forEachNeighbour(n, [&](long m) { near = near || d.values[n] + d.values[m] <= h; });
    if (near) evaluate(n);
  });
  // Flood across free edges; a piece with no node evaluated (none, unless the mesh lies
  // outside the grid) gets one evaluation.
  std::vector<char> evaluated(count);
  std::vector<long> queue;
  for (long n = 0; n < long(count); ++n)
    if ((evaluated[n] = whole[n] != kUnknown)) queue.push_back(n);
  long popped = 0;
  for (long seed = 0;; ++seed) {
    while (!queue.empty()) {
      if (stop(++popped)) return inside;
      const long n = queue.back();
      queue.pop_back();
      forEachNeighbour(n, [&](long m) {
        if (whole[m] == kUnknown && crossesNothing(n, m)) whole[m] = whole[n], queue.push_back(m);
      });
    }
    while (seed < long(count) && whole[seed] != kUnknown) ++seed;
    if (seed == long(count)) break;
    evaluate(seed);
    evaluated[seed] = 1;
    queue.push_back(seed);
  }
  // Elsewhere w_mesh = W - w_cone, its sign checked as an estimate's.
  ParallelFor(long(count), [&](long n) {
    if (!stop(n) && !evaluated[n]) {
      const Point3 p = node(n);
      inside[n] = winding.Inside(p, double(whole[n]) - coneWinding(p));
    }
  });
  return inside;
}

} // namespace

// in:  mesh — triangle mesh, closed or with holes; grid — the lattice
// out: f(node) = +/- distance to the nearest surface point (distance_transform.h),
//      negative where the generalized winding number is >= 1/2 (DESIGN.md: sdf.h).
namespace {

template <class Gradient> ScalarField Signed(const Mesh &mesh, const Grid &grid, Gradient *gradient, const Interrupt &interrupt) {
  ScalarField f = UnsignedDistance(mesh, grid, gradient, interrupt);
  if (interrupt.Cancelled()) return f;
  const WindingNumber winding(mesh);
  const std::vector<char> inside = Inside(f, winding, ClosingCone(mesh), interrupt);
  if (interrupt.Stop()) return f;
  ParallelFor(long(f.values.size()), [&](long n) {
    if (inside[n]) {
      f.values[n] = -f.values[n];
      if (gradient && f.values[n] < 0) gradient->values[n] = -gradient->values[n];  // not on the surface: the normal
    }
  });
  return f;
}

} // namespace

ScalarField SignedDistance(const Mesh &mesh, const Grid &grid, VectorField *gradient, const Interrupt &interrupt) {
  return Signed(mesh, grid, gradient, interrupt);
}

ScalarField SignedDistance(const Mesh &mesh, const Grid &grid, GradientField *gradient, const Interrupt &interrupt) {
  return Signed(mesh, grid, gradient, interrupt);
}

} // namespace eulermap
