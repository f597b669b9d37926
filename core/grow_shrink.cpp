#include "grow_shrink.h"
#include "parallel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <queue>

namespace eulermap {

namespace {

constexpr double kUnreached = std::numeric_limits<double>::infinity();

// A move to one of the 26 neighbours, with the paths of grid edges that join its ends
// inside the cell (none for an edge move; 2 of one corner for a face diagonal, 6 of two
// corners for a body diagonal).
struct Move {
  vcg::Point3i offset;
  double length = 0;  // in cells
  std::vector<std::array<vcg::Point3i, 2>> paths;  // corners passed; the second is unused for a face diagonal
};

std::vector<Move> Moves() {
  std::vector<Move> moves;
  for (int z = -1; z <= 1; ++z)
    for (int y = -1; y <= 1; ++y)
      for (int x = -1; x <= 1; ++x) {
        const int axes = std::abs(x) + std::abs(y) + std::abs(z);
        if (axes == 0) continue;
        Move m;
        m.offset = vcg::Point3i(x, y, z);
        m.length = std::sqrt(double(axes));
        const int d[3] = {x, y, z};
        auto along = [&](int a) {
          vcg::Point3i p(0, 0, 0);
          p[a] = d[a];
          return p;
        };
        std::vector<int> used;
        for (int a = 0; a < 3; ++a)
          if (d[a]) used.push_back(a);
        if (axes == 2) {
          for (int a : used) m.paths.push_back({along(a), along(a)});
        } else if (axes == 3) {
          for (int a : used)
            for (int b : used)
              if (a != b) m.paths.push_back({along(a), along(a) + along(b)});
        }
        moves.push_back(m);
      }
  return moves;
}

// The withdrawing set's function at a node, u from 0 (the whole set) to 1 (the kept set):
// u toKept - (1 - u) fromOutside, a blend of the node's distance (within the set) to the
// kept nodes and its way in from the outside (CarveDistance); negative while the node stays.
// Nodes leave in the order of fromOutside / (fromOutside + toKept), from 0 next to the
// outside to 1 next to the kept set: a node leaves after the nodes between it and the
// outside (no cavity is born) and before those between it and the kept set (no piece is left
// away from it, as it would be if the deepest from the outside left last: a cage's centre).
double Withdrawn(double toKept, double fromOutside, double u) {
  if (toKept == kUnreached) return u > 0 ? kUnreached : -fromOutside;  // no kept node to withdraw onto: gone at once
  if (fromOutside == kUnreached) return u < 1 ? -kUnreached : toKept;   // enclosed by the kept set: kept to the end
  return u * toKept - (1 - u) * fromOutside;
}

// Calls visit(m) for each neighbour m of node n within the grid: its 6 face neighbours, or
// all 26.
template <class Visit> void ForNeighbours(const Grid &g, std::size_t n, bool facesOnly, Visit &&visit) {
  const vcg::Point3i p = g.Coordinates(n);
  for (int c = -1; c <= 1; ++c)
    for (int b = -1; b <= 1; ++b)
      for (int a = -1; a <= 1; ++a) {
        const int i = p.X() + a, j = p.Y() + b, k = p.Z() + c;
        if ((a || b || c) && (!facesOnly || std::abs(a) + std::abs(b) + std::abs(c) == 1) && i >= 0 && j >= 0 &&
            k >= 0 && i < g.dims.X() && j < g.dims.Y() && k < g.dims.Z())
          visit(g.Index(i, j, k));
      }
}

// Whether node n lies on the grid's border (beyond which is outside).
bool OnGridBorder(const Grid &g, std::size_t n) {
  const vcg::Point3i p = g.Coordinates(n);
  return std::min({p.X(), p.Y(), p.Z(), g.dims.X() - 1 - p.X(), g.dims.Y() - 1 - p.Y(), g.dims.Z() - 1 - p.Z()}) == 0;
}

// The length of the step between neighbouring nodes a and b: h, sqrt 2 h or sqrt 3 h.
double StepLength(const Grid &g, std::size_t a, std::size_t b) {
  const vcg::Point3i d = g.Coordinates(a) - g.Coordinates(b);
  return g.h * std::sqrt(double(d.X() * d.X() + d.Y() * d.Y() + d.Z() * d.Z()));
}

// The widest paths from the nodes `start` holds: per node that `through` holds, the most over
// paths from a start node through such nodes (over the 6 face neighbours where facesOnly,
// else all 26) of the least `value` along them; -infinity where no path reaches (and off
// `through`).
std::vector<double> Widest(const Grid &g, const std::vector<char> &start, bool facesOnly, const std::vector<char> &through,
                           const std::vector<double> &value) {
  std::vector<double> widest(through.size(), -kUnreached);
  std::priority_queue<std::pair<double, std::size_t>> queue;  // the widest first
  for (std::size_t n = 0; n < through.size(); ++n)
    if (through[n] && start[n]) widest[n] = value[n], queue.push({value[n], n});
  while (!queue.empty()) {
    const auto [w, n] = queue.top();
    queue.pop();
    if (w < widest[n]) continue;
    ForNeighbours(g, n, facesOnly, [&, w = w](std::size_t q) {
      if (!through[q]) return;
      const double least = std::min(w, value[q]);
      if (least > widest[q]) widest[q] = least, queue.push({least, q});
    });
  }
  return widest;
}

// Widest from the outside (the nodes not in `inside` and beyond the grid, 26-connected as
// zero_set_topology.h's complement), through nodes of `inside`.
std::vector<double> WidestFromOutside(const Grid &g, const std::vector<char> &inside, const std::vector<char> &through,
                                      const std::vector<double> &value) {
  std::vector<char> start(inside.size(), 0);
  for (std::size_t n = 0; n < inside.size(); ++n) {
    if (!through[n]) continue;
    start[n] = OnGridBorder(g, n);
    ForNeighbours(g, n, false, [&](std::size_t q) { start[n] = start[n] || !inside[q]; });
  }
  return Widest(g, start, false, through, value);
}

// Whether leaving in the order of the distance to the kept set, the farthest first, would
// bear a cavity: a node of `inside` not kept that the outside reaches only past nodes nearer
// the kept set by more than a cell (WidestFromOutside, in the least toKept along the path).
// A cup's floor lies farther from the cup than its mouth does; a node no path from the
// outside reaches is a cavity under every order, and does not count.
bool FarthestFirstBearsACavity(const Grid &g, const std::vector<char> &inside, const std::vector<char> &kept,
                               const std::vector<double> &toKept) {
  std::vector<char> withdrawing(inside.size());
  for (std::size_t n = 0; n < inside.size(); ++n) withdrawing[n] = inside[n] && !kept[n];
  const std::vector<double> widest = WidestFromOutside(g, inside, withdrawing, toKept);
  for (std::size_t n = 0; n < inside.size(); ++n)
    if (withdrawing[n] && widest[n] > -kUnreached && widest[n] < toKept[n] - g.h) return true;
  return false;
}

// Whether joining the nodes of X1 nearest X0 first would fold a pocket: a node of X1 outside
// X0 where the fronts from X0 meet (none of its 6-neighbours within G farther from X0) lies
// deeper from the outside than from X0 by more than two cells. A cup's inside filled so
// grows from its walls inward; the walls meet along its axis and the tracked surface folds
// there (cup -> mug at 64 cells: 2.82% of the mapped area flipped). The fronts that meet in
// the middle of a rail grown from its two ends lie near the outside, and do not count.
bool NearestFirstFoldsAPocket(const Grid &g, const std::vector<char> &inside, const std::vector<char> &x0,
                              const std::vector<double> &d0, const std::vector<double> &fromOutside) {
  for (std::size_t n = 0; n < inside.size(); ++n) {
    if (!inside[n] || x0[n] || d0[n] == kUnreached || fromOutside[n] == kUnreached ||
        fromOutside[n] <= d0[n] + 2 * g.h)
      continue;
    bool ridge = true;
    ForNeighbours(g, n, true, [&](std::size_t m) { ridge = ridge && !(inside[m] && d0[m] > d0[n]); });
    if (ridge) return true;
  }
  return false;
}

// The order in which the nodes of X1 outside X0 join where the nearest-first order folds a
// pocket: tau = d0 - c (c the way in from the outside), the deepest from the outside first
// and, at one depth, the nearest X0 first: a cup's inside fills from its floor up, its walls
// taken in as the front rises past them. Closed so that the inside sets keep their topology:
// a node joins no earlier than its 6-neighbours on some path from X0 (J, the least over
// 6-paths from X0 of the most tau along them: no node joins alone), and no later than the
// nodes on some path to the outside (the most over 26-paths from the outside of the least J
// along them: no node is enclosed before it joins). Returned shifted to start at one cell,
// 0 in X0 and +infinity where d0 is.
std::vector<double> PistonOrder(const Grid &g, const std::vector<char> &inside, const std::vector<char> &x0,
                                const std::vector<double> &d0, const std::vector<double> &fromOutside) {
  const std::size_t count = inside.size();
  auto joining = [&](std::size_t n) { return inside[n] && !x0[n] && d0[n] < kUnreached; };
  double deepest = 0;
  for (std::size_t n = 0; n < count; ++n)
    if (joining(n) && fromOutside[n] < kUnreached) deepest = std::max(deepest, fromOutside[n]);
  std::vector<double> tau(count, kUnreached);
  for (std::size_t n = 0; n < count; ++n)
    if (joining(n)) tau[n] = d0[n] - (fromOutside[n] < kUnreached ? fromOutside[n] : deepest);  // enclosed by X0: first
  // J: the least over 6-paths from X0 of the most tau along them.
  std::vector<double> joined(count, kUnreached);
  {
    std::priority_queue<std::pair<double, std::size_t>, std::vector<std::pair<double, std::size_t>>, std::greater<>> queue;
    for (std::size_t n = 0; n < count; ++n) {
      if (!joining(n)) continue;
      bool byX0 = false;
      ForNeighbours(g, n, true, [&](std::size_t q) { byX0 = byX0 || x0[q]; });
      if (byX0) joined[n] = tau[n], queue.push({tau[n], n});
    }
    while (!queue.empty()) {
      const auto [j, n] = queue.top();
      queue.pop();
      if (j > joined[n]) continue;
      ForNeighbours(g, n, true, [&, j = j](std::size_t q) {
        if (!joining(q)) return;
        const double through = std::max(j, tau[q]);
        if (through < joined[q]) joined[q] = through, queue.push({through, q});
      });
    }
  }
  // The most over 26-paths from the outside of the least J along them (at most J).
  std::vector<char> reached(count);
  for (std::size_t n = 0; n < count; ++n) reached[n] = joining(n) && joined[n] < kUnreached;
  std::vector<double> order = WidestFromOutside(g, inside, reached, joined);
  double first = kUnreached;
  for (std::size_t n = 0; n < count; ++n) {
    if (reached[n] && order[n] == -kUnreached) order[n] = joined[n];  // enclosed by X0
    if (reached[n]) first = std::min(first, order[n]);
  }
  for (std::size_t n = 0; n < count; ++n)
    order[n] = x0[n] && inside[n] ? 0 : reached[n] ? order[n] - first + g.h : kUnreached;
  return order;
}

// The carve's order from the outside: flooded over the 26 neighbours (the outside's
// connectivity in zero_set_topology.h), tau(n) = max(r(n), tau(m) + (1 - tau(m)) |n - m| /
// (2 (|n - m| + d1(n)))) for the neighbour m it is reached from (r = c / (c + d1)): every node
// leaves after a neighbour on a path from the outside, so no cavity is born; where r does not
// rise inward (behind a neck) the flood goes on towards the kept set at half the pace r has
// along a straight way in. Nodes `carved` holds only; the rest +infinity.
std::vector<double> CarveFlood(const Grid &g, const std::vector<char> &carved, const std::vector<double> &toKept,
                               const std::vector<double> &fromOutside) {
  const std::size_t count = carved.size();
  auto ratio = [&](std::size_t n) { return fromOutside[n] / (fromOutside[n] + toKept[n]); };
  std::vector<double> tau(count, kUnreached);
  using Entry = std::pair<double, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (std::size_t n = 0; n < count; ++n) {
    if (!carved[n]) continue;
    bool byOutside = OnGridBorder(g, n);
    ForNeighbours(g, n, false, [&](std::size_t q) { byOutside = byOutside || fromOutside[q] == 0; });
    if (byOutside) tau[n] = ratio(n), queue.push({tau[n], n});
  }
  while (!queue.empty()) {
    const auto [t, n] = queue.top();
    queue.pop();
    if (t > tau[n]) continue;
    ForNeighbours(g, n, false, [&, t = t](std::size_t q) {
      if (!carved[q]) return;
      const double step = StepLength(g, n, q);
      const double through = std::max(ratio(q), t + (1 - t) * step / (2 * (step + toKept[q])));
      if (through < tau[q]) tau[q] = through, queue.push({through, q});
    });
  }
  return tau;
}

// The carve (grow then withdraw where the farthest-first order would bear a cavity): per
// withdrawing node, the u at which it leaves. r = c / (c + d1) (c the way in from the outside,
// CarveDistance; d1 the distance to the kept set) rises from 0 at the outside to 1 at the kept
// set along a straight way in. Read node by node it is not closed where the way narrows: a
// vase's neck lies near the kept set all along (d1 small), so its nodes left after the wide
// hollow below, which was born as a cavity (sphere -> vase at 64 cells: 62% covered). So it
// is closed twice: flooded from the outside (CarveFlood: no cavity is born), then from the
// kept set, the most over 6-paths from it of the least flood time along them, so that no
// node leaves after every node between it and the kept set (the flood from a cage's six
// windows meets last at its centre, away from the bars); a peak is cut to the pass that joins
// it to the kept set, and leaves with it. Withdrawing nodes with both distances finite only;
// the rest +infinity.
std::vector<double> CarveOrder(const Grid &g, const std::vector<char> &withdrawing, const std::vector<char> &kept,
                               const std::vector<double> &toKept, const std::vector<double> &fromOutside) {
  const std::size_t count = withdrawing.size();
  std::vector<char> carved(count);
  for (std::size_t n = 0; n < count; ++n) carved[n] = withdrawing[n] && toKept[n] < kUnreached && fromOutside[n] < kUnreached;
  const std::vector<double> flood = CarveFlood(g, carved, toKept, fromOutside);
  std::vector<char> byKept(count, 0);
  for (std::size_t n = 0; n < count; ++n)
    if (carved[n]) ForNeighbours(g, n, true, [&](std::size_t q) { byKept[n] = byKept[n] || kept[q]; });
  std::vector<double> order = Widest(g, byKept, true, carved, flood);
  for (std::size_t n = 0; n < count; ++n)
    if (!carved[n] || order[n] == -kUnreached) order[n] = flood[n];  // not joined to the kept set
  return order;
}

} // namespace

std::vector<double> DistanceWithin(const Grid &g, const std::vector<char> &inside, const std::vector<char> &seed) {
  std::vector<double> d(g.NodeCount(), kUnreached);
  using Entry = std::pair<double, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (std::size_t n = 0; n < d.size(); ++n)
    if (seed[n] && inside[n]) d[n] = 0, queue.push({0.0, n});
  const std::vector<Move> moves = Moves();
  const int nx = g.dims.X(), ny = g.dims.Y(), nz = g.dims.Z();
  auto in = [&](const vcg::Point3i &p) {
    return p.X() >= 0 && p.Y() >= 0 && p.Z() >= 0 && p.X() < nx && p.Y() < ny && p.Z() < nz &&
           inside[g.Index(p.X(), p.Y(), p.Z())];
  };
  while (!queue.empty()) {
    const auto [dist, n] = queue.top();
    queue.pop();
    if (dist > d[n]) continue;
    const vcg::Point3i p = g.Coordinates(n);
    for (const Move &m : moves) {
      const vcg::Point3i q = p + m.offset;
      if (!in(q)) continue;
      bool joined = m.paths.empty();
      for (const auto &path : m.paths) joined = joined || (in(p + path[0]) && in(p + path[1]));
      if (!joined) continue;
      const std::size_t i = g.Index(q.X(), q.Y(), q.Z());
      const double e = dist + m.length * g.h;
      if (e < d[i]) d[i] = e, queue.push({e, i});
    }
  }
  return d;
}

std::vector<double> CarveDistance(const Grid &g, const std::vector<char> &inside, const std::vector<char> &kept) {
  // Paths run through `inside` and the nodes within two of it: the outside's nodes all lie at
  // 0, so a path enters from a node next to `inside`, and the corners of its diagonal step lie
  // within two (DistanceWithin). Farther nodes of the outside are set to 0 after.
  const std::size_t count = inside.size();
  std::vector<char> near(inside), through(count), outside(count);
  for (int axis = 0; axis < 3; ++axis) {  // dilated by two along each axis in turn: a 5^3 box
    const std::vector<char> before = near;
    for (std::size_t n = 0; n < count; ++n) {
      if (!before[n]) continue;
      const vcg::Point3i p = g.Coordinates(n);
      for (int step = -2; step <= 2; ++step) {
        vcg::Point3i q = p;
        q[axis] += step;
        if (q[axis] >= 0 && q[axis] < g.dims[axis]) near[g.Index(q.X(), q.Y(), q.Z())] = 1;
      }
    }
  }
  for (std::size_t n = 0; n < count; ++n) through[n] = near[n] && !kept[n], outside[n] = !inside[n];
  std::vector<double> d = DistanceWithin(g, through, outside);
  for (std::size_t n = 0; n < count; ++n)
    if (!inside[n]) d[n] = 0;
  return d;
}

GrowShrink::GrowShrink(const ScalarField &f0, const ScalarField &f1) : f0_(f0), f1_(f1) {
  const std::size_t count = f0.values.size();
  std::vector<char> inside(count), x0(count), x1(count);
  for (std::size_t n = 0; n < count; ++n) {
    x0[n] = f0.values[n] < 0;
    x1[n] = f1.values[n] < 0;
    inside[n] = x0[n] || x1[n];
  }
  d0_ = DistanceWithin(f0.grid, inside, x0);
  {
    const std::vector<double> fromOutside = CarveDistance(f0.grid, inside, x0);
    if (NearestFirstFoldsAPocket(f0.grid, inside, x0, d0_, fromOutside)) d0_ = PistonOrder(f0.grid, inside, x0, d0_, fromOutside);
  }
  d1_ = DistanceWithin(f0.grid, inside, x1);
  for (std::size_t n = 0; n < count; ++n) {
    if (x1[n] && d0_[n] < kUnreached) l0_ = std::max(l0_, d0_[n]);
    if (x0[n] && d1_[n] < kUnreached) l1_ = std::max(l1_, d1_[n]);
  }
  if (FarthestFirstBearsACavity(f0.grid, inside, x1, d1_)) {
    carve_ = CarveDistance(f0.grid, inside, x1);
    // Withdrawn's blend u d1 - (1 - u) c, zero at u = c / (c + d1), made zero at the carve's
    // order tau instead: c and d1 become tau L and (1 - tau) L, L = c + d1.
    std::vector<char> withdrawing(count);
    for (std::size_t n = 0; n < count; ++n) withdrawing[n] = inside[n] && !x1[n];
    const std::vector<double> tau = CarveOrder(f0.grid, withdrawing, x1, d1_, carve_);
    for (std::size_t n = 0; n < count; ++n)
      if (tau[n] < kUnreached) {
        const double length = carve_[n] + d1_[n];
        carve_[n] = tau[n] * length, d1_[n] = (1 - tau[n]) * length;
      }
  }
  switch_ = l0_ + l1_ > 0 ? l0_ / (l0_ + l1_) : 0.5;
}

void GrowShrink::Frame(double t, ScalarField &out) const {
  out.grid = f0_.grid;
  if (t <= 0 || t >= 1) {  // f0 and f1 exactly
    out.values = t <= 0 ? f0_.values : f1_.values;
    return;
  }
  out.values.resize(f0_.values.size());
  const long long count = (long long)out.values.size();
  const bool grow = t <= switch_;
  const double s = grow ? (switch_ > 0 ? t / switch_ : 1) : (switch_ < 1 ? (1 - t) / (1 - switch_) : 0);
  ParallelFor(count, [&](long n) {
    const double a = f0_.values[n], b = f1_.values[n];
    if (grow)
      out.values[n] = std::min(a, std::max(b, d0_[n] - s * l0_));
    else
      out.values[n] = std::min(b, std::max(a, carve_.empty() ? d1_[n] - s * l1_ : Withdrawn(d1_[n], carve_[n], 1 - s)));
  });
}

} // namespace eulermap
