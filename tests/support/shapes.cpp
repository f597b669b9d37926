#include "shapes.h"

#include "fields.h"

#include "meshes.h"

#include "core/quality.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>

namespace eulermap::testing {

namespace {

using Sdf = std::function<double(const Point3 &)>;

double Ball(const Point3 &p, const Point3 &c, double r) { return (p - c).Norm() - r; }

double Torus(const Point3 &p, const Point3 &c, double R, double r) {
  const Point3 q = p - c;
  return std::hypot(std::hypot(q.X(), q.Y()) - R, q.Z()) - r;
}

double Ellipsoid(const Point3 &p, const Point3 &radii) {  // a bound, exact on the surface's sign
  const Point3 q(p.X() / radii.X(), p.Y() / radii.Y(), p.Z() / radii.Z());
  return (q.Norm() - 1) * std::min({radii.X(), radii.Y(), radii.Z()});
}

// A box from lo to hi (exact signed distance).
double Block(const Point3 &p, const Point3 &lo, const Point3 &hi) {
  const Point3 c = (lo + hi) / 2, e = (hi - lo) / 2;
  const Point3 q(std::abs(p.X() - c.X()) - e.X(), std::abs(p.Y() - c.Y()) - e.Y(), std::abs(p.Z() - c.Z()) - e.Z());
  const Point3 out(std::max(q.X(), 0.0), std::max(q.Y(), 0.0), std::max(q.Z(), 0.0));
  return out.Norm() + std::min(std::max({q.X(), q.Y(), q.Z()}), 0.0);
}

// A capsule: the segment from a to b thickened by r.
double Capsule(const Point3 &p, const Point3 &a, const Point3 &b, double r) {
  const Point3 ab = b - a;
  const double t = std::clamp(((p - a) * ab) / ab.SquaredNorm(), 0.0, 1.0);
  return (p - (a + ab * t)).Norm() - r;
}

Sdf Union(std::vector<Sdf> parts) {
  return [parts](const Point3 &p) {
    double d = 1e300;
    for (const Sdf &s : parts) d = std::min(d, s(p));
    return d;
  };
}

Sdf Row(int n, double spacing, const std::function<double(const Point3 &, const Point3 &)> &one) {
  std::vector<Sdf> parts;
  for (int i = 0; i < n; ++i) {
    const Point3 c((i - (n - 1) / 2.0) * spacing, 0, 0);
    parts.push_back([c, one](const Point3 &p) { return one(p, c); });
  }
  return Union(parts);
}

// A tube of radius r round a curve c(u), u in [0, 1], sampled at n segments; closed where c(1) = c(0).
Sdf Tube(const std::function<Point3(double)> &c, double r, int n = 360) {
  std::vector<Point3> at(n + 1);
  for (int i = 0; i <= n; ++i) at[i] = c(double(i) / n);
  return [at, r](const Point3 &p) {
    double d = 1e300;
    for (size_t i = 0; i + 1 < at.size(); ++i) d = std::min(d, Capsule(p, at[i], at[i + 1], r));
    return d;
  };
}
Point3 TrefoilKnot(double u) {  // (sin t + 2 sin 2t, cos t - 2 cos 2t, -sin 3t) / 4
  const double t = 2 * M_PI * u;
  return Point3(std::sin(t) + 2 * std::sin(2 * t), std::cos(t) - 2 * std::cos(2 * t), -std::sin(3 * t)) * 0.25;
}
Point3 Helix(double u) {  // three turns of radius 0.4, 1 high
  const double t = 6 * M_PI * u;
  return Point3(0.4 * std::cos(t), 0.4 * std::sin(t), u - 0.5);
}

// Furniture: a seat 0.8 square at height 0.45-0.55, legs 0.1 square, a back 0.8 wide.
constexpr double kLeg = 0.1, kHalf = 0.4;
std::vector<Sdf> Seat(double top) {
  std::vector<Sdf> parts = {[top](const Point3 &p) { return Block(p, Point3(-kHalf, -kHalf, top - 0.1), Point3(kHalf, kHalf, top)); }};
  for (double x : {-kHalf, kHalf - kLeg})
    for (double y : {-kHalf, kHalf - kLeg})
      parts.push_back([x, y, top](const Point3 &p) { return Block(p, Point3(x, y, 0), Point3(x + kLeg, y + kLeg, top - 0.05)); });
  return parts;
}
void AddRails(std::vector<Sdf> &parts) {  // stretchers at height 0.15-0.25, between neighbouring legs
  parts.push_back([](const Point3 &p) { return Block(p, Point3(-kHalf, -kHalf, 0.15), Point3(kHalf, -kHalf + kLeg, 0.25)); });
  parts.push_back([](const Point3 &p) { return Block(p, Point3(-kHalf, kHalf - kLeg, 0.15), Point3(kHalf, kHalf, 0.25)); });
  parts.push_back([](const Point3 &p) { return Block(p, Point3(-kHalf, -kHalf, 0.15), Point3(-kHalf + kLeg, kHalf, 0.25)); });
  parts.push_back([](const Point3 &p) { return Block(p, Point3(kHalf - kLeg, -kHalf, 0.15), Point3(kHalf, kHalf, 0.25)); });
}
void AddSolidBack(std::vector<Sdf> &parts) {
  parts.push_back([](const Point3 &p) { return Block(p, Point3(-kHalf, kHalf - kLeg, 0.5), Point3(kHalf, kHalf, 1.3)); });
}
void AddSlattedBack(std::vector<Sdf> &parts) {  // two posts, a top rail and two slats: 3 gaps
  parts.push_back([](const Point3 &p) { return Block(p, Point3(-kHalf, kHalf - kLeg, 0.5), Point3(-kHalf + kLeg, kHalf, 1.3)); });
  parts.push_back([](const Point3 &p) { return Block(p, Point3(kHalf - kLeg, kHalf - kLeg, 0.5), Point3(kHalf, kHalf, 1.3)); });
  parts.push_back([](const Point3 &p) { return Block(p, Point3(-kHalf, kHalf - kLeg, 1.2), Point3(kHalf, kHalf, 1.3)); });
  for (double x : {-0.15, 0.05})
    parts.push_back([x](const Point3 &p) { return Block(p, Point3(x, kHalf - kLeg, 0.5), Point3(x + kLeg, kHalf, 1.25)); });
}

struct Made {
  Shape shape;
  Sdf sdf;
  Box3 box;
};

std::vector<Made> Catalogue() {
  std::vector<Made> all;
  const Box3 unit(Point3(-1, -1, -1), Point3(1, 1, 1));
  all.push_back({{"sphere", 1, 0}, [](const Point3 &p) { return Ball(p, Point3(0, 0, 0), 0.7); }, unit});
  for (int g = 1; g <= 4; ++g) {
    const double half = 0.45 * (g - 1) + 0.8;
    all.push_back({{"ring" + std::to_string(g), 1, g},
                   Row(g, 0.9, [](const Point3 &p, const Point3 &c) { return Torus(p, c, 0.5, 0.18); }),
                   Box3(Point3(-half, -0.8, -0.3), Point3(half, 0.8, 0.3))});
  }
  for (int n = 2; n <= 3; ++n) {
    const double half = 0.65 * (n - 1) + 0.6;
    all.push_back({{"spheres" + std::to_string(n), n, 0},
                   Row(n, 1.3, [](const Point3 &p, const Point3 &c) { return Ball(p, c, 0.5); }),
                   Box3(Point3(-half, -0.6, -0.6), Point3(half, 0.6, 0.6))});
    const double length = 0.65 * (n - 1) + 0.5;
    all.push_back({{"blob" + std::to_string(n), 1, 0},
                   [length](const Point3 &p) { return Ellipsoid(p, Point3(length, 0.5, 0.5)); },
                   Box3(Point3(-length - 0.1, -0.6, -0.6), Point3(length + 0.1, 0.6, 0.6))});
  }
  const Box3 furniture(Point3(-0.5, -0.5, -0.1), Point3(0.5, 0.5, 1.4));
  std::vector<Sdf> chair = Seat(0.55);
  AddSolidBack(chair);
  all.push_back({{"chair", 1, 0}, Union(chair), furniture});
  std::vector<Sdf> rails = Seat(0.55);
  AddSolidBack(rails);
  AddRails(rails);
  all.push_back({{"chair_rails", 1, 4}, Union(rails), furniture});
  std::vector<Sdf> slats = Seat(0.55);
  AddSlattedBack(slats);
  all.push_back({{"chair_slats", 1, 3}, Union(slats), furniture});
  all.push_back({{"table", 1, 0}, Union(Seat(0.75)), Box3(Point3(-0.5, -0.5, -0.1), Point3(0.5, 0.5, 0.85))});
  std::vector<Sdf> stool = Seat(0.65);
  AddRails(stool);
  all.push_back({{"stool", 1, 4}, Union(stool), Box3(Point3(-0.5, -0.5, -0.1), Point3(0.5, 0.5, 0.75))});
  std::vector<Sdf> bench = {[](const Point3 &p) { return Block(p, Point3(-0.8, -0.25, 0.4), Point3(0.8, 0.25, 0.5)); }};
  for (double x : {-0.8, 0.7}) {  // a leg at each corner, a rail between the two legs of each end
    for (double y : {-0.25, 0.15})
      bench.push_back([x, y](const Point3 &p) { return Block(p, Point3(x, y, 0), Point3(x + kLeg, y + kLeg, 0.45)); });
    bench.push_back([x](const Point3 &p) { return Block(p, Point3(x, -0.25, 0.12), Point3(x + kLeg, 0.25, 0.2)); });
  }
  all.push_back({{"bench", 1, 2}, Union(bench), Box3(Point3(-0.9, -0.35, -0.1), Point3(0.9, 0.35, 0.6))});
  all.push_back({{"frame", 1, 1},  // a picture frame: a slab 1.4 x 1 with a window 1 x 0.6
                 [](const Point3 &p) {
                   return std::max(Block(p, Point3(-0.7, -0.5, -0.06), Point3(0.7, 0.5, 0.06)),
                                   -Block(p, Point3(-0.5, -0.3, -1), Point3(0.5, 0.3, 1)));
                 },
                 Box3(Point3(-0.8, -0.6, -0.16), Point3(0.8, 0.6, 0.16))});
  all.push_back({{"mug", 1, 1},  // a solid cylinder with a handle, half a torus, on its side
                 [](const Point3 &p) {
                   const double body = std::max(std::hypot(p.X(), p.Y()) - 0.4, std::abs(p.Z()) - 0.5);
                   const double handle = std::hypot(std::hypot(p.X() - 0.4, p.Z()) - 0.25, p.Y()) - 0.07;
                   return std::min(body, handle);
                 },
                 Box3(Point3(-0.5, -0.5, -0.6), Point3(0.8, 0.5, 0.6))});
  std::vector<Sdf> ladder;  // two stiles and five rungs
  for (double x : {-0.3, 0.22})
    ladder.push_back([x](const Point3 &p) { return Block(p, Point3(x, -0.05, -1), Point3(x + 0.08, 0.05, 1)); });
  for (int r = 0; r < 5; ++r)
    ladder.push_back([r](const Point3 &p) {
      const double z = -0.8 + 0.4 * r;
      return Block(p, Point3(-0.3, -0.04, z - 0.04), Point3(0.3, 0.04, z + 0.04));
    });
  all.push_back({{"ladder", 1, 4}, Union(ladder), Box3(Point3(-0.4, -0.15, -1.1), Point3(0.4, 0.15, 1.1))});
  all.push_back({{"dumbbell", 1, 0},  // two balls joined by a bar
                 Union({[](const Point3 &p) { return Ball(p, Point3(-0.6, 0, 0), 0.35); },
                        [](const Point3 &p) { return Ball(p, Point3(0.6, 0, 0), 0.35); },
                        [](const Point3 &p) { return Block(p, Point3(-0.6, -0.1, -0.1), Point3(0.6, 0.1, 0.1)); }}),
                 Box3(Point3(-1.05, -0.45, -0.45), Point3(1.05, 0.45, 0.45))});
  // Shapes made after the families, to check them on inputs they were not tuned on.
  for (int holes = 2; holes <= 3; ++holes)  // a flat oval slab with round holes in a row
    all.push_back({{"plate" + std::to_string(holes), 1, holes},
                   [holes](const Point3 &p) {
                     double d = Ellipsoid(Point3(p.X(), p.Y(), p.Z()), Point3(0.45 * holes + 0.2, 0.45, 0.15));
                     for (int h = 0; h < holes; ++h)
                       d = std::max(d, 0.16 - std::hypot(p.X() - (h - (holes - 1) / 2.0) * 0.5, p.Y()));
                     return d;
                   },
                   Box3(Point3(-0.45 * holes - 0.3, -0.55, -0.25), Point3(0.45 * holes + 0.3, 0.55, 0.25))});
  all.push_back({{"thin_ring", 1, 1}, [](const Point3 &p) { return Torus(p, Point3(0, 0, 0), 0.6, 0.1); },
                 Box3(Point3(-0.8, -0.8, -0.2), Point3(0.8, 0.8, 0.2))});
  all.push_back({{"box_tunnel", 1, 1},  // a cube pierced by a square tunnel
                 [](const Point3 &p) {
                   return std::max(Block(p, Point3(-0.5, -0.5, -0.5), Point3(0.5, 0.5, 0.5)),
                                   -Block(p, Point3(-0.2, -1, -0.2), Point3(0.2, 1, 0.2)));
                 },
                 Box3(Point3(-0.6, -0.6, -0.6), Point3(0.6, 0.6, 0.6))});
  all.push_back({{"two_balls", 2, 0},  // a large and a small ball apart
                 Union({[](const Point3 &p) { return Ball(p, Point3(-0.35, 0, 0), 0.6); },
                        [](const Point3 &p) { return Ball(p, Point3(0.75, 0, 0), 0.3); }}),
                 Box3(Point3(-1.05, -0.7, -0.7), Point3(1.15, 0.7, 0.7))});
  all.push_back({{"snowman", 1, 0},  // the same two balls, overlapping
                 Union({[](const Point3 &p) { return Ball(p, Point3(-0.2, 0, 0), 0.6); },
                        [](const Point3 &p) { return Ball(p, Point3(0.55, 0, 0), 0.3); }}),
                 Box3(Point3(-0.9, -0.7, -0.7), Point3(0.95, 0.7, 0.7))});
  std::vector<Sdf> arms = Seat(0.55);  // a chair with arm rests on posts from the seat's front corners
  AddSolidBack(arms);
  for (double x : {-kHalf, kHalf - kLeg}) {
    arms.push_back([x](const Point3 &p) { return Block(p, Point3(x, -kHalf, 0.5), Point3(x + kLeg, -kHalf + kLeg, 0.85)); });
    arms.push_back([x](const Point3 &p) { return Block(p, Point3(x, -kHalf, 0.8), Point3(x + kLeg, kHalf, 0.9)); });
  }
  all.push_back({{"armchair", 1, 2}, Union(arms), furniture});
  // Shapes made in session 32, after every rule above, to check the pipeline on shapes it was not tuned on.
  std::vector<Sdf> pretzel;  // three rings in a triangle, each overlapping the other two
  for (int k = 0; k < 3; ++k) {
    const double a = M_PI / 2 + 2 * M_PI * k / 3;
    const Point3 c(0.5 * std::cos(a), 0.5 * std::sin(a), 0);
    pretzel.push_back([c](const Point3 &p) { return Torus(p, c, 0.42, 0.14); });
  }
  all.push_back({{"pretzel", 1, 3}, Union(pretzel), Box3(Point3(-1.1, -0.9, -0.25), Point3(1.1, 1.15, 0.25))});
  all.push_back({{"spectacles", 1, 2},  // two thin rings and a bridge
                 Union({[](const Point3 &p) { return Torus(p, Point3(-0.5, 0, 0), 0.35, 0.09); },
                        [](const Point3 &p) { return Torus(p, Point3(0.5, 0, 0), 0.35, 0.09); },
                        [](const Point3 &p) { return Block(p, Point3(-0.2, -0.05, -0.05), Point3(0.2, 0.05, 0.05)); }}),
                 Box3(Point3(-1, -0.55, -0.2), Point3(1, 0.55, 0.2))});
  all.push_back({{"key", 1, 1},  // a ring, a shaft and two teeth
                 Union({[](const Point3 &p) { return Torus(p, Point3(-0.5, 0, 0), 0.3, 0.09); },
                        [](const Point3 &p) { return Block(p, Point3(-0.25, -0.05, -0.04), Point3(0.8, 0.05, 0.04)); },
                        [](const Point3 &p) { return Block(p, Point3(0.5, -0.2, -0.04), Point3(0.58, 0, 0.04)); },
                        [](const Point3 &p) { return Block(p, Point3(0.68, -0.2, -0.04), Point3(0.76, 0, 0.04)); }}),
                 Box3(Point3(-0.95, -0.5, -0.15), Point3(0.9, 0.5, 0.15))});
  std::vector<Sdf> hand = {[](const Point3 &p) { return Ellipsoid(p, Point3(0.35, 0.42, 0.12)); }};
  for (double x : {-0.24, -0.08, 0.08, 0.24})
    hand.push_back([x](const Point3 &p) { return Capsule(p, Point3(x, 0.3, 0), Point3(x * 1.2, 0.8 - 3 * x * x, 0), 0.065); });
  hand.push_back([](const Point3 &p) { return Capsule(p, Point3(0.25, -0.05, 0), Point3(0.6, 0.3, 0), 0.075); });
  all.push_back({{"hand", 1, 0}, Union(hand), Box3(Point3(-0.5, -0.55, -0.25), Point3(0.75, 0.95, 0.25))});
  std::vector<Sdf> star = {[](const Point3 &p) { return Ball(p, Point3(0, 0, 0), 0.4); }};
  for (int axis = 0; axis < 3; ++axis)
    for (double side : {-1.0, 1.0}) {
      Point3 tip(0, 0, 0);
      tip[axis] = 0.85 * side;
      star.push_back([tip](const Point3 &p) { return Capsule(p, Point3(0, 0, 0), tip, 0.08); });
    }
  all.push_back({{"star", 1, 0}, Union(star), Box3(Point3(-1, -1, -1), Point3(1, 1, 1))});
  all.push_back({{"cage", 1, 5},  // the twelve edges of a cube as bars
                 [](const Point3 &p) { return CubeFrameDistance(p, 0.5, 0.06); },
                 Box3(Point3(-0.7, -0.7, -0.7), Point3(0.7, 0.7, 0.7))});
  all.push_back({{"cup", 1, 1},  // an open cylinder with a floor and the mug's handle
                 [](const Point3 &p) {
                   const double r = std::hypot(p.X(), p.Y());
                   const double outer = std::max(r - 0.4, std::abs(p.Z()) - 0.5);
                   const double inner = std::max(r - 0.32, -0.42 - p.Z());
                   const double handle = std::max(std::hypot(std::hypot(p.X() - 0.4, p.Z()) - 0.25, p.Y()) - 0.07, 0.36 - p.X());
                   return std::min(std::max(outer, -inner), handle);
                 },
                 Box3(Point3(-0.5, -0.5, -0.6), Point3(0.8, 0.5, 0.6))});
  std::vector<Sdf> round = {[](const Point3 &p) { return std::max(std::hypot(p.X(), p.Y()) - 0.5, std::abs(p.Z() - 0.72) - 0.04); },
                            [](const Point3 &p) { return std::max(std::hypot(p.X(), p.Y()) - 0.06, std::abs(p.Z() - 0.4) - 0.3); }};
  for (int k = 0; k < 3; ++k) {
    const double a = 2 * M_PI * k / 3;
    round.push_back([a](const Point3 &p) { return Capsule(p, Point3(0, 0, 0.12), Point3(0.4 * std::cos(a), 0.4 * std::sin(a), 0.04), 0.045); });
  }
  all.push_back({{"round_table", 1, 0}, Union(round), Box3(Point3(-0.6, -0.6, -0.1), Point3(0.6, 0.6, 0.85))});
  // Shapes made in session 35, after every rule above, to check the pipeline on shapes it was not tuned on.
  std::vector<Sdf> wheel = {[](const Point3 &p) { return Torus(p, Point3(0, 0, 0), 0.7, 0.08); },
                            [](const Point3 &p) { return Ball(p, Point3(0, 0, 0), 0.15); }};
  for (int k = 0; k < 5; ++k) {
    const double a = 2 * M_PI * k / 5;
    wheel.push_back([a](const Point3 &p) { return Capsule(p, Point3(0, 0, 0), Point3(0.7 * std::cos(a), 0.7 * std::sin(a), 0), 0.05); });
  }
  all.push_back({{"wheel", 1, 5}, Union(wheel), Box3(Point3(-0.85, -0.85, -0.2), Point3(0.85, 0.85, 0.2))});
  all.push_back({{"trefoil", 1, 1}, Tube(TrefoilKnot, 0.1), Box3(Point3(-0.85, -0.85, -0.4), Point3(0.85, 0.85, 0.4))});
  all.push_back({{"spring", 1, 0}, Tube(Helix, 0.08), Box3(Point3(-0.55, -0.55, -0.7), Point3(0.55, 0.55, 0.7))});
  all.push_back({{"link", 2, 2},  // two rings interlocked, 0.1 apart where they pass
                 Union({[](const Point3 &p) { return Torus(p, Point3(-0.3, 0, 0), 0.45, 0.1); },
                        [](const Point3 &p) { return Torus(Point3(p.X(), p.Z(), p.Y()), Point3(0.3, 0, 0), 0.45, 0.1); }}),
                 Box3(Point3(-0.9, -0.6, -0.6), Point3(0.9, 0.6, 0.6))});
  all.push_back({{"bowl", 1, 0},  // half a spherical shell 0.1 thick, open upwards
                 [](const Point3 &p) { return std::max({Ball(p, Point3(0, 0, 0.2), 0.7), -Ball(p, Point3(0, 0, 0.2), 0.6), p.Z() - 0.2}); },
                 Box3(Point3(-0.8, -0.8, -0.6), Point3(0.8, 0.8, 0.3))});
  all.push_back({{"vase", 1, 0},  // a hollow ball with a narrow neck, walls 0.1 thick
                 [](const Point3 &p) {
                   const double body = Ball(p, Point3(0, 0, -0.15), 0.58), neck = std::max(std::hypot(p.X(), p.Y()) - 0.18, std::abs(p.Z() - 0.45) - 0.3);
                   const double hollow = Ball(p, Point3(0, 0, -0.15), 0.48), mouth = std::max(std::hypot(p.X(), p.Y()) - 0.08, -0.1 - p.Z());
                   return std::max(std::min(body, neck), -std::min(hollow, mouth));
                 },
                 Box3(Point3(-0.7, -0.7, -0.8), Point3(0.7, 0.7, 0.85))});
  all.push_back({{"bookcase", 1, 0},  // a box with a back panel and two shelves' pockets open at the front
                 [](const Point3 &p) {
                   return std::max({Block(p, Point3(-0.5, -0.2, -0.7), Point3(0.5, 0.2, 0.7)),
                                    -Block(p, Point3(-0.4, -0.5, 0.05), Point3(0.4, 0.12, 0.6)),
                                    -Block(p, Point3(-0.4, -0.5, -0.6), Point3(0.4, 0.12, -0.05))});
                 },
                 Box3(Point3(-0.6, -0.3, -0.8), Point3(0.6, 0.3, 0.8))});
  all.push_back({{"teapot", 1, 1},  // a body, a handle, a spout and a knob on the lid
                 Union({[](const Point3 &p) { return Ellipsoid(p, Point3(0.5, 0.5, 0.38)); },
                        [](const Point3 &p) { return std::max(std::hypot(std::hypot(p.X() - 0.45, p.Z()) - 0.25, p.Y()) - 0.06, 0.4 - p.X()); },
                        [](const Point3 &p) { return Capsule(p, Point3(-0.3, 0, -0.05), Point3(-0.8, 0, 0.3), 0.06); },
                        [](const Point3 &p) { return Ball(p, Point3(0, 0, 0.42), 0.08); }}),
                 Box3(Point3(-0.95, -0.6, -0.5), Point3(0.85, 0.6, 0.6))});
  all.push_back({{"hare", 1, 0},  // a body, a head and two long thin ears
                 Union({[](const Point3 &p) { return Ellipsoid(p, Point3(0.45, 0.3, 0.3)); },
                        [](const Point3 &p) { return Ball(p, Point3(0.45, 0, 0.3), 0.18); },
                        [](const Point3 &p) { return Capsule(p, Point3(0.45, -0.1, 0.4), Point3(0.4, -0.2, 0.9), 0.045); },
                        [](const Point3 &p) { return Capsule(p, Point3(0.45, 0.1, 0.4), Point3(0.4, 0.2, 0.9), 0.045); }}),
                 Box3(Point3(-0.6, -0.45, -0.45), Point3(0.75, 0.45, 1.0))});
  // Shapes made in session 36, after every rule above, to check the pipeline on shapes it was not tuned on.
  std::vector<Sdf> square;  // four rings in a square, each overlapping its two neighbours (and a fifth hole amid them)
  for (double x : {-0.42, 0.42})
    for (double y : {-0.42, 0.42}) square.push_back([x, y](const Point3 &p) { return Torus(p, Point3(x, y, 0), 0.45, 0.13); });
  all.push_back({{"ring_square", 1, 5}, Union(square), Box3(Point3(-1.1, -1.1, -0.25), Point3(1.1, 1.1, 0.25))});
  all.push_back({{"fat_ring", 1, 1}, [](const Point3 &p) { return Torus(p, Point3(0, 0, 0), 0.45, 0.33); },  // a hole 0.24 across
                 Box3(Point3(-0.9, -0.9, -0.45), Point3(0.9, 0.9, 0.45))});
  std::vector<Sdf> four;  // four balls in a square, apart
  for (double x : {-0.5, 0.5})
    for (double y : {-0.5, 0.5}) four.push_back([x, y](const Point3 &p) { return Ball(p, Point3(x, y, 0), 0.38); });
  all.push_back({{"spheres4", 4, 0}, Union(four), Box3(Point3(-1, -1, -0.5), Point3(1, 1, 0.5))});
  all.push_back({{"peanut", 1, 0},  // two balls fused through a waist
                 Union({[](const Point3 &p) { return Ball(p, Point3(-0.4, 0, 0), 0.45); },
                        [](const Point3 &p) { return Ball(p, Point3(0.4, 0, 0), 0.45); }}),
                 Box3(Point3(-0.95, -0.55, -0.55), Point3(0.95, 0.55, 0.55))});
  std::vector<Sdf> shelf;  // four posts through three shelves
  for (double x : {-0.45, 0.37})
    for (double y : {-0.2, 0.12}) shelf.push_back([x, y](const Point3 &p) { return Block(p, Point3(x, y, 0), Point3(x + 0.08, y + 0.08, 1.2)); });
  for (double z : {0.15, 0.6, 1.05}) shelf.push_back([z](const Point3 &p) { return Block(p, Point3(-0.45, -0.2, z), Point3(0.45, 0.2, z + 0.06)); });
  all.push_back({{"shelf", 1, 6}, Union(shelf), Box3(Point3(-0.55, -0.3, -0.1), Point3(0.55, 0.3, 1.3))});
  std::vector<Sdf> three = {[](const Point3 &p) { return std::max(std::hypot(p.X(), p.Y()) - 0.4, std::abs(p.Z() - 0.65) - 0.05); },
                            [](const Point3 &p) { return Torus(p, Point3(0, 0, 0.25), 0.3, 0.035); }};
  for (int k = 0; k < 3; ++k) {  // three splayed legs through a ring
    const double a = 2 * M_PI * k / 3;
    three.push_back([a](const Point3 &p) { return Capsule(p, Point3(0.25 * std::cos(a), 0.25 * std::sin(a), 0.62), Point3(0.35 * std::cos(a), 0.35 * std::sin(a), 0.03), 0.045); });
  }
  all.push_back({{"stool3", 1, 3}, Union(three), Box3(Point3(-0.5, -0.5, -0.1), Point3(0.5, 0.5, 0.8))});
  std::vector<Sdf> htable = Seat(0.75);  // a table with an H of stretchers between its legs
  for (double x : {-kHalf, kHalf - kLeg})
    htable.push_back([x](const Point3 &p) { return Block(p, Point3(x, -kHalf, 0.2), Point3(x + kLeg, kHalf, 0.28)); });
  htable.push_back([](const Point3 &p) { return Block(p, Point3(-kHalf, -0.04, 0.2), Point3(kHalf, 0.04, 0.28)); });
  all.push_back({{"table_h", 1, 3}, Union(htable), Box3(Point3(-0.5, -0.5, -0.1), Point3(0.5, 0.5, 0.85))});
  std::vector<Sdf> throne = Seat(0.55);  // arm rests and a slatted back
  AddSlattedBack(throne);
  for (double x : {-kHalf, kHalf - kLeg}) {
    throne.push_back([x](const Point3 &p) { return Block(p, Point3(x, -kHalf, 0.5), Point3(x + kLeg, -kHalf + kLeg, 0.85)); });
    throne.push_back([x](const Point3 &p) { return Block(p, Point3(x, -kHalf, 0.8), Point3(x + kLeg, kHalf, 0.9)); });
  }
  all.push_back({{"throne", 1, 5}, Union(throne), furniture});
  return all;
}

} // namespace

const std::vector<Shape> &Shapes() {
  static const std::vector<Shape> shapes = [] {
    std::vector<Shape> s;
    for (const Made &m : Catalogue()) s.push_back(m.shape);
    return s;
  }();
  return shapes;
}

Eigen::Matrix3d ShapeTurn(const std::string &name, std::string *base) {
  // NAME_turned: a quarter turn about x, (x, y, z) -> (x, -z, y); NAME_tilted: 40 degrees about
  // x, then 25 about y.
  std::string rest = name;
  auto ends = [&](const std::string &suffix) {
    if (rest.size() <= suffix.size() || rest.compare(rest.size() - suffix.size(), suffix.size(), suffix) != 0) return false;
    rest.resize(rest.size() - suffix.size());
    return true;
  };
  Eigen::Matrix3d turn = Eigen::Matrix3d::Identity();
  if (ends("_turned"))
    turn = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  else if (ends("_tilted"))
    turn = (Eigen::AngleAxisd(25 * M_PI / 180, Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(40 * M_PI / 180, Eigen::Vector3d::UnitX()))
               .toRotationMatrix();
  if (base) *base = rest;
  return turn;
}

void MakeShape(const std::string &name, Mesh &m, int cells) {
  // The shape's function is read at R^T p, its box turned with it.
  std::string base;
  const Eigen::Matrix3d turn = ShapeTurn(name, &base);
  for (const Made &made : Catalogue()) {
    if (made.shape.name != base) continue;
    const Sdf sdf = made.sdf;
    const Eigen::Matrix3d back = turn.transpose();
    Box3 box;
    for (int c = 0; c < 8; ++c) {
      const Eigen::Vector3d corner((c & 1 ? made.box.max : made.box.min).X(), (c & 2 ? made.box.max : made.box.min).Y(),
                                   (c & 4 ? made.box.max : made.box.min).Z());
      const Eigen::Vector3d turned = turn * corner;
      box.Add(Point3(turned.x(), turned.y(), turned.z()));
    }
    return MakeImplicit(m, [sdf, back](const Point3 &p) {
      const Eigen::Vector3d q = back * Eigen::Vector3d(p.X(), p.Y(), p.Z());
      return sdf(Point3(q.x(), q.y(), q.z()));
    }, box, cells);
  }
  throw std::invalid_argument("no shape named " + name);
}

FamilyFigures Figures(const std::string &source, const std::string &target, int cells, const Mesh &targetMesh,
                      const Result &result, double seconds) {
  const Report &rep = result.report;
  FamilyFigures f;
  for (const EventSurgery &s : rep.surgery) {
    if (s.outcome != EventCut::Cut) continue;
    const TopologyEventKind kind = rep.topologyEvents[s.event].kind;
    ++f.eventsCut;
    (kind == TopologyEventKind::HandleGained || kind == TopologyEventKind::PartsMerged ? f.discPairs : f.bands) += 1;
  }
  f.longestShare = LongestEdge(result.mapped) / targetMesh.bbox.Diag();
  char line[1024];
  std::snprintf(line, sizeof line,
                "family | %s -> %s | %d | events %zu, %d cut (%d disc pairs, %d bands) | cut %d/%d/%d | needed %d/%d/%d "
                "| coverage %.2f%% | flipped %.2f%% (%.2f%% before untangling) | longest %.2f%% of the diagonal | %s | %.1f s\n",
                source.c_str(), target.c_str(), cells, rep.topologyEvents.size(), f.eventsCut, f.discPairs, f.bands,
                rep.cutComponents, rep.cutBoundaryLoops, rep.cutEulerCharacteristic, rep.neededComponents,
                rep.neededBoundaryLoops, rep.neededEulerCharacteristic, 100 * rep.quality.coverage,
                100 * rep.quality.flippedAreaShare, 100 * rep.quality.flippedBeforeUntangling, 100 * f.longestShare,
                rep.morphMode.substr(0, rep.morphMode.find(' ')).c_str(), seconds);
  f.line = line;
  return f;
}

} // namespace eulermap::testing
