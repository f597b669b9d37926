#include "fields.h"

#include <algorithm>
#include <cmath>

namespace eulermap::testing {

ScalarField Sampled(const Grid &g, const std::function<double(const Point3 &)> &f) {
  ScalarField out(g, 0.0);
  g.ForEachNode([&](int i, int j, int k, std::size_t n) { out.values[n] = f(g.Node(i, j, k)); });
  return out;
}

std::function<double(const Point3 &)> Ball(const Point3 &c, double r) {
  return [=](const Point3 &p) { return vcg::Distance(p, c) - r; };
}

std::vector<char> Inside(const ScalarField &f) {
  std::vector<char> in(f.values.size());
  for (std::size_t n = 0; n < in.size(); ++n) in[n] = f.values[n] < 0;
  return in;
}

BallScene::BallScene(double xa, double ra, double xb, double rb) {
  g.origin = Point3(-2, -1.2, -1.2);
  g.h = 0.1;
  g.dims = vcg::Point3i(41, 25, 25);
  f0 = Sampled(g, Ball(Point3(-1.1, 0, 0), 0.6));
  const auto a = Ball(Point3(xa, 0, 0), ra), b = Ball(Point3(xb, 0, 0), rb);
  f1 = Sampled(g, [=](const Point3 &p) { return std::min(a(p), b(p)); });
}

double CubeFrameDistance(const Point3 &p, double half, double bar) {
  double d = 1e300;
  for (int axis = 0; axis < 3; ++axis)
    for (double u : {-half, half})
      for (double v : {-half, half}) {
        Point3 lo, hi;
        lo[axis] = -half - bar, hi[axis] = half + bar;
        lo[(axis + 1) % 3] = u - bar, hi[(axis + 1) % 3] = u + bar;
        lo[(axis + 2) % 3] = v - bar, hi[(axis + 2) % 3] = v + bar;
        d = std::min(d, BoxSignedDistance(Box3(lo, hi), p));
      }
  return d;
}

CageScene::CageScene() {
  g.origin = Point3(-1.2, -1.2, -1.2);
  g.h = 0.06;
  g.dims = vcg::Point3i(41, 41, 41);
  f0 = Sampled(g, Ball(Point3(0, 0, 0), 1.1));
  f1 = Sampled(g, [](const Point3 &p) { return CubeFrameDistance(p, 0.5, 0.09); });
}

CupScene::CupScene() {
  g.origin = Point3(-0.9, -0.9, -0.9);
  g.h = 0.04;
  g.dims = vcg::Point3i(46, 46, 46);
  f0 = Sampled(g, Ball(Point3(0.1, 0.05, 0.1), 0.75));
  f1 = Sampled(g, [](const Point3 &p) {
    const double r = std::hypot(p.X(), p.Y());
    return std::max(std::max(r - 0.4, std::abs(p.Z()) - 0.5), -std::max(r - 0.32, -0.42 - p.Z()));
  });
}

VaseScene::VaseScene() {
  g.origin = Point3(-0.9, -0.9, -0.9);
  g.h = 0.04;
  g.dims = vcg::Point3i(46, 46, 46);
  f0 = Sampled(g, Ball(Point3(0.05, 0.03, 0.0), 0.78));
  f1 = Sampled(g, [](const Point3 &p) {
    const double r = std::hypot(p.X(), p.Y()), body = std::hypot(r, p.Z() + 0.2);
    const double outer = std::min(body - 0.55, std::max(r - 0.18, std::abs(p.Z() - 0.45) - 0.4));
    const double hollow = std::min(body - 0.43, std::max(r - 0.09, -p.Z()));
    return std::max(outer, -hollow);
  });
}

VectorField LinearField(const double A[3][3], const Point3 &c) {
  Grid g;
  g.origin = Point3(-1, -1, -1);
  g.h = 2.0 / 15;
  g.dims = vcg::Point3i(16, 16, 16);
  VectorField V(g, Point3(0, 0, 0));
  g.ForEachNode([&](int i, int j, int k, std::size_t n) {
    const Point3 d = g.Node(i, j, k) - c;
    for (int r = 0; r < 3; ++r) V.values[n][r] = A[r][0] * d[0] + A[r][1] * d[1] + A[r][2] * d[2];
  });
  return V;
}

ScalarField Quadric(const Grid &g, const Point3 &c, const Point3 &curvature) {
  ScalarField f(g, 0.0);
  g.ForEachNode([&](int i, int j, int k, std::size_t n) {
    const Point3 d = g.Node(i, j, k) - c;
    f.values[n] = curvature[0] * d[0] * d[0] + curvature[1] * d[1] * d[1] + curvature[2] * d[2] * d[2];
  });
  return f;
}

double BoxSignedDistance(const Box3 &box, const Point3 &p) {
  const Point3 c = box.Center(), half = box.Dim() / 2;
  double outside = 0, inside = -1e300;
  for (int a = 0; a < 3; ++a) {
    const double q = std::abs(p[a] - c[a]) - half[a];
    outside += std::max(q, 0.0) * std::max(q, 0.0);
    inside = std::max(inside, q);
  }
  return inside > 0 ? std::sqrt(outside) : inside;
}

TopologyEvent EventAt(const Grid &g, const vcg::Point3i &node, TopologyEventKind kind) {
  TopologyEvent e;
  e.node = node;
  e.position = g.Node(node[0], node[1], node[2]);
  e.kind = kind;
  return e;
}

} // namespace eulermap::testing
