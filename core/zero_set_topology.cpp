#include "zero_set_topology.h"

#include "interrupt.h"
#include "union_find.h"

#include <algorithm>
#include <array>
#include <climits>
#include <stdexcept>
#include <utility>

namespace eulermap {

namespace {

// ---- The 3x3x3 neighbourhood as 27-bit masks: position (dx+1) + 3 (dy+1) + 9 (dz+1).

constexpr int kCentre = 13;

constexpr int Offset(int position, int axis) {  // -1, 0 or 1
  return (axis == 0 ? position : axis == 1 ? position / 3 : position / 9) % 3 - 1;
}
constexpr int Abs(int v) { return v < 0 ? -v : v; }
constexpr int StepsApart(int p, int q) {  // grid edges between two positions (L1 distance)
  return Abs(Offset(p, 0) - Offset(q, 0)) + Abs(Offset(p, 1) - Offset(q, 1)) + Abs(Offset(p, 2) - Offset(q, 2));
}
constexpr bool OneCellApart(int p, int q) {  // 26-adjacent (Chebyshev distance 1)
  return p != q && Abs(Offset(p, 0) - Offset(q, 0)) <= 1 && Abs(Offset(p, 1) - Offset(q, 1)) <= 1 &&
         Abs(Offset(p, 2) - Offset(q, 2)) <= 1;
}

constexpr std::uint32_t MaskWithin(int minSteps, int maxSteps) {  // positions minSteps..maxSteps edges from the centre
  std::uint32_t m = 0;
  for (int p = 0; p < 27; ++p)
    if (StepsApart(p, kCentre) >= minSteps && StepsApart(p, kCentre) <= maxSteps) m |= 1u << p;
  return m;
}
constexpr std::uint32_t kN6 = MaskWithin(1, 1);   // the 6 face neighbours
constexpr std::uint32_t kN18 = MaskWithin(1, 2);  // the 18-neighbourhood, centre excluded
constexpr std::uint32_t kN26 = MaskWithin(1, 3);  // the 26-neighbourhood, centre excluded

using Table = std::array<std::uint32_t, 27>;

constexpr Table Adjacency(bool faces) {  // per position: the positions 6-adjacent (faces) or 26-adjacent to it
  Table t{};
  for (int p = 0; p < 27; ++p)
    for (int q = 0; q < 27; ++q)
      if (faces ? StepsApart(p, q) == 1 : OneCellApart(p, q)) t[p] |= 1u << q;
  return t;
}
constexpr Table kAdjacent6 = Adjacency(true);
constexpr Table kAdjacent26 = Adjacency(false);

// Per neighbour q: the corners other than the centre of the grid cell spanned by the centre
// and q (an edge, a square or a cube: every position whose offset is 0 or q's on each axis).
constexpr Table CellCorners() {
  Table t{};
  for (int q = 0; q < 27; ++q)
    for (int r = 0; r < 27; ++r) {
      bool corner = r != kCentre;
      for (int a = 0; a < 3; ++a) corner = corner && (Offset(r, a) == 0 || Offset(r, a) == Offset(q, a));
      if (corner && q != kCentre) t[q] |= 1u << r;
    }
  return t;
}
constexpr Table kCellCorners = CellCorners();

// in:  set (positions), adjacency (per position, its neighbours), seed (a position of set)
// out: the component of set containing seed
std::uint32_t Flood(std::uint32_t set, const Table &adjacent, int seed) {
  std::uint32_t component = 1u << seed, frontier = component;
  while (frontier) {
    std::uint32_t next = 0;
    for (std::uint32_t f = frontier; f; f &= f - 1) next |= adjacent[__builtin_ctz(f)];
    frontier = next & set & ~component;
    component |= frontier;
  }
  return component;
}

// in:  set (positions), adjacency, seeds (positions)
// out: the components of set that contain a seed
std::vector<std::uint32_t> LocalPieces(std::uint32_t set, const Table &adjacent, std::uint32_t seeds) {
  std::vector<std::uint32_t> pieces;
  for (std::uint32_t left = seeds & set; left; left &= ~pieces.back())
    pieces.push_back(Flood(set, adjacent, __builtin_ctz(left)));
  return pieces;
}

// in:  X around the centre (centre's bit ignored)
// out: the pieces T6 counts (6-components of X in N18 holding a 6-neighbour) and those T26
//      counts (26-components of X' in N26)
std::vector<std::uint32_t> InsidePieces(std::uint32_t x) { return LocalPieces(x & kN18, kAdjacent6, kN6); }
std::vector<std::uint32_t> OutsidePieces(std::uint32_t x) { return LocalPieces(~x & kN26, kAdjacent26, kN26); }

// in:  X around the centre, the centre not in X
// out: chi(K(X + centre)) - chi(K(X)): the centre and every cell it completes, signed by dimension
int StarEulerCharacteristic(std::uint32_t x) {
  int chi = 1;
  for (int q = 0; q < 27; ++q)
    if (q != kCentre && (kCellCorners[q] & ~x) == 0) chi += StepsApart(q, kCentre) % 2 ? -1 : 1;
  return chi;
}

// ---- The grid as a graph: node n's neighbour at position p is node n + delta[p].

struct Lattice {
  explicit Lattice(const Grid &grid) : dims(grid.dims) {
    for (int p = 0; p < 27; ++p)
      delta[p] = Offset(p, 0) + long(dims[0]) * (Offset(p, 1) + long(dims[1]) * Offset(p, 2));
  }
  // in: a node's index; out: its (i, j, k)
  vcg::Point3i Node(std::size_t n) const {
    return vcg::Point3i(int(n % dims[0]), int(n / dims[0] % dims[1]), int(n / (std::size_t(dims[0]) * dims[1])));
  }
  bool OnBorder(const vcg::Point3i &c) const {
    return c[0] == 0 || c[1] == 0 || c[2] == 0 || c[0] == dims[0] - 1 || c[1] == dims[1] - 1 || c[2] == dims[2] - 1;
  }
  // in: node c; out: the positions of its neighbourhood that lie on the grid
  std::uint32_t OnGrid(const vcg::Point3i &c) const {
    if (!OnBorder(c)) return (1u << 27) - 1;
    std::uint32_t m = 0;
    for (int p = 0; p < 27; ++p) {
      bool in = true;
      for (int a = 0; a < 3; ++a) in = in && c[a] + Offset(p, a) >= 0 && c[a] + Offset(p, a) < dims[a];
      if (in) m |= 1u << p;
    }
    return m;
  }
  // in: node n, positions around it; out: fn(neighbour) called for each of them on the grid
  template <class Fn> void ForEach(std::size_t n, std::uint32_t mask, Fn &&fn) const {
    for (std::uint32_t m = mask & OnGrid(Node(n)); m; m &= m - 1) fn(At(n, __builtin_ctz(m)));
  }
  // in: node n, a position around it on the grid; out: that node
  std::size_t At(std::size_t n, int position) const { return std::size_t(long(n) + delta[position]); }

  vcg::Point3i dims;
  std::array<long, 27> delta;  // index step to each position
};

// Component labels of X (6-adjacency) and of X' (26-adjacency; label 0 is the unbounded
// component: every node of X' on the grid's border, and what they reach).
struct Labelling {
  std::vector<int> label;  // per node: among X's labels or the complement's, by its side
  int components = 0, cavities = 0;
};

// in:  X (per node, 1 if in X) on the lattice, poll (may be empty; may throw to cancel)
// out: its labelling, by depth-first flood fills: X's components 0, 1, ... and the
//      cavities 1, 2, ... in the storage order of their first node; poll called every
//      kNodesBetweenPolls nodes visited (interrupt.h)
Labelling Label(const Lattice &lattice, const std::vector<std::uint8_t> &inside, const std::function<void()> &poll) {
  Labelling l;
  // Every pass over the nodes asks poll every kNodesBetweenPolls nodes, the labels' first
  // fill too (fresh pages are cleared at their first touch: 0.26 s unpolled at 256^3).
  l.label.reserve(inside.size());
  for (std::size_t n = 0; n < inside.size(); n += kNodesBetweenPolls) {
    l.label.insert(l.label.end(), std::min(kNodesBetweenPolls, inside.size() - n), -1);
    if (poll) poll();
  }
  std::vector<std::size_t> stack;
  std::size_t visited = 0;
  auto fill = [&](bool side, std::uint32_t adjacency, int id) {
    while (!stack.empty()) {
      if (poll && ++visited % kNodesBetweenPolls == 0) poll();
      const std::size_t n = stack.back();
      stack.pop_back();
      lattice.ForEach(n, adjacency, [&](std::size_t y) {
        if (l.label[y] < 0 && bool(inside[y]) == side) l.label[y] = id, stack.push_back(y);
      });
    }
  };
  for (std::size_t n = 0; n < inside.size(); ++n) {
    if (poll && n % kNodesBetweenPolls == 0) poll();
    if (!inside[n] && l.label[n] < 0 && lattice.OnBorder(lattice.Node(n))) l.label[n] = 0, stack.push_back(n);
  }
  fill(false, kN26, 0);
  for (std::size_t n = 0; n < inside.size(); ++n) {
    if (poll && n % kNodesBetweenPolls == 0) poll();
    if (l.label[n] >= 0) continue;
    const bool side = inside[n];
    const int id = side ? l.components++ : 1 + l.cavities++;
    l.label[n] = id;
    stack.push_back(n);
    fill(side, side ? kN6 : kN26, id);
  }
  return l;
}

// in:  X on the lattice, poll (may be empty; called once a plane; may throw to cancel)
// out: chi(K(X)) = #nodes - #edges + #squares - #cubes, the cells with all corners in X
int EulerCharacteristic(const Lattice &lattice, const std::vector<std::uint8_t> &inside,
                        const std::function<void()> &poll) {
  const long dx = lattice.dims[0], dy = lattice.dims[1], dz = lattice.dims[2];
  const long sy = dx, sz = dx * dy;
  long chi = 0;
  for (long k = 0; k < dz; ++k) {
    if (poll) poll();
    for (long j = 0; j < dy; ++j)
      for (long i = 0; i < dx; ++i) {
        const long n = i + sy * j + sz * k;
        if (!inside[n]) continue;
        const bool x = i + 1 < dx && inside[n + 1], y = j + 1 < dy && inside[n + sy];
        const bool z = k + 1 < dz && inside[n + sz];
        const bool xy = x && y && inside[n + 1 + sy], xz = x && z && inside[n + 1 + sz];
        const bool yz = y && z && inside[n + sy + sz];
        const bool xyz = xy && xz && yz && inside[n + 1 + sy + sz];
        chi += 1 - (x + y + z) + (xy + xz + yz) - xyz;
      }
  }
  return int(chi);
}

// in: f; out: per node, 1 if f < 0 there (in X)
std::vector<std::uint8_t> InsideSet(const ScalarField &f, const Interrupt &interrupt = Interrupt()) {
  std::vector<std::uint8_t> inside;
  FillPolling(inside, f.values.size(), [&f](std::size_t n) { return std::uint8_t(f.values[n] < 0); }, interrupt);
  return inside;
}

} // namespace

ZeroSetTopology Measure(const ScalarField &f) {
  const Lattice lattice(f.grid);
  const std::vector<std::uint8_t> inside = InsideSet(f);
  const Labelling l = Label(lattice, inside, {});
  ZeroSetTopology t;
  t.components = l.components;
  t.cavities = l.cavities;
  t.eulerCharacteristic = EulerCharacteristic(lattice, inside, {});
  t.parts.resize(l.components);
  std::vector<Point3> sum(l.components, Point3(0, 0, 0));
  f.grid.ForEachNode([&](int i, int j, int k, std::size_t n) {
    if (!inside[n]) return;
    ++t.parts[l.label[n]].nodes;
    sum[l.label[n]] += Point3(i, j, k);
  });
  for (int c = 0; c < l.components; ++c)
    t.parts[c].centroid = f.grid.origin + sum[c] * (f.grid.h / t.parts[c].nodes);
  return t;
}

bool IsSimple(std::uint32_t neighbourhood) {
  return InsidePieces(neighbourhood).size() == 1 && OutsidePieces(neighbourhood).size() == 1;
}

const char *Name(TopologyEventKind kind) {
  switch (kind) {
    case TopologyEventKind::ComponentBorn: return "component born";
    case TopologyEventKind::ComponentDied: return "component died";
    case TopologyEventKind::PartsMerged: return "parts merged";
    case TopologyEventKind::PartSplit: return "part split";
    case TopologyEventKind::HandleGained: return "handle gained";
    case TopologyEventKind::HandleLost: return "handle lost";
    case TopologyEventKind::CavityBorn: return "cavity born";
    case TopologyEventKind::CavityFilled: return "cavity filled";
    case TopologyEventKind::CavityOpened: return "cavity opened";
  }
  return "?";
}

TopologyChange Effect(TopologyEventKind kind) {
  TopologyChange c;
  switch (kind) {
    case TopologyEventKind::ComponentBorn: case TopologyEventKind::PartSplit: c.components = 1; break;
    case TopologyEventKind::ComponentDied: case TopologyEventKind::PartsMerged: c.components = -1; break;
    case TopologyEventKind::HandleGained: c.handles = 1; break;
    case TopologyEventKind::HandleLost: c.handles = -1; break;
    case TopologyEventKind::CavityBorn: c.cavities = 1; break;
    case TopologyEventKind::CavityFilled: case TopologyEventKind::CavityOpened: c.cavities = -1; break;
  }
  return c;
}

TopologyChange Effect(const std::vector<TopologyEvent> &events) {
  TopologyChange sum;
  for (const TopologyEvent &e : events) {
    const TopologyChange c = Effect(e.kind);
    sum.components += c.components, sum.handles += c.handles, sum.cavities += c.cavities;
  }
  return sum;
}

TopologyChange Difference(const ZeroSetTopology &before, const ZeroSetTopology &after) {
  TopologyChange c;
  c.components = after.components - before.components;
  c.handles = after.Handles() - before.Handles();
  c.cavities = after.cavities - before.cavities;
  return c;
}

// ---- InsideSetTracker

namespace {

// A local piece of X or X' around a flipped node x: one that T6 or T26 counts.
struct Piece {
  std::uint32_t positions;  // around x
  bool beyondGrid;          // holds positions beyond the grid: then it is in the complement's label 0
};

} // namespace

struct InsideSetTracker::State {
  State(const ScalarField &first, const std::function<void()> &poll);

  // in:  x, a node whose sign changes; where in the step it crosses 0; the step
  // out: x moved to the other side; labels, counts and chi updated; events appended
  void Flip(std::size_t x, double crossing, int step, std::vector<TopologyEvent> &events);
  // in:  x, now on `side` (true: X), the local pieces of that side around it
  // out: x labelled; the components around x joined into one. Returns how many distinct
  //      components the pieces belonged to (0: x is a component alone).
  int Join(std::size_t x, bool side, const std::vector<Piece> &pieces);
  // in:  x, now off `side`, the local pieces of that side around it
  // out: the components of side - {x} that the pieces fall into, found by searches from each
  //      piece in turns; every one but one labelled afresh. Returns how many there are (0: x
  //      was a component alone).
  int Part(std::size_t x, bool side, const std::vector<Piece> &pieces);
  // in:  a side, a label of it
  // out: the label's root; label 0 of X' stays a root
  int Root(bool side, int id) { return Labels(side).Find(id); }
  UnionFind &Labels(bool side) { return side ? insideLabels : outsideLabels; }

  Grid grid;
  Lattice lattice;
  std::vector<std::uint8_t> inside;  // per node: in X in the current frame
  std::vector<double> value;         // per node: f in the current frame
  std::vector<int> label;            // per node: its component's label, on its side (Labelling)
  UnionFind insideLabels, outsideLabels;  // each side's labels, by component
  int components = 0, complementComponents = 0, eulerCharacteristic = 0;
  std::vector<int> mark;  // per node: base + index of the search of Part that reached it
  int markBase = 0;       // marks below it are from earlier calls of Part
};

InsideSetTracker::State::State(const ScalarField &first, const std::function<void()> &poll)
    : grid(first.grid), lattice(first.grid) {
  // The per-node arrays filled a piece at a time with a poll after each (interrupt.h: the
  // kernel clears fresh pages at their first touch; at 384^3 they took a second unpolled).
  const HeldThrow reporting(poll);
  inside = InsideSet(first, reporting.interrupt());
  FillPolling(value, first.values.size(), [&first](std::size_t n) { return first.values[n]; }, reporting.interrupt());
  AssignPolling(mark, first.values.size(), -1, reporting.interrupt());
  reporting.Rethrow();
  Labelling l = Label(lattice, inside, poll);
  label = std::move(l.label);
  components = l.components;
  complementComponents = 1 + l.cavities;
  eulerCharacteristic = EulerCharacteristic(lattice, inside, poll);
  insideLabels = UnionFind(components);
  outsideLabels = UnionFind(complementComponents);
}

void InsideSetTracker::State::Flip(std::size_t x, double crossing, int step, std::vector<TopologyEvent> &events) {
  const vcg::Point3i c = lattice.Node(x);
  const std::uint32_t onGrid = lattice.OnGrid(c);
  std::uint32_t around = 0;  // X around x
  for (std::uint32_t m = onGrid & kN26; m; m &= m - 1)
    if (inside[lattice.At(x, __builtin_ctz(m))]) around |= 1u << __builtin_ctz(m);
  std::vector<Piece> in, out;
  for (std::uint32_t p : InsidePieces(around)) in.push_back({p, false});
  for (std::uint32_t p : OutsidePieces(around)) out.push_back({p, (p & ~onGrid) != 0});

  const bool joins = !inside[x];  // x joins X (else it leaves X)
  inside[x] = joins;
  const std::vector<Piece> &gaining = joins ? in : out, &losing = joins ? out : in;
  const int joined = Join(x, joins, gaining), parts = Part(x, !joins, losing);
  if (in.size() == 1 && out.size() == 1) return;  // a simple point (T6 = T26 = 1): nothing changed

  // The side gaining x: its components around x become one; every piece beyond the first
  // in a component closes a loop through x. The side losing x: its component falls into
  // `parts`; every piece beyond the first in a part was on a loop through x. A loop of X'
  // is a handle of X as much as a loop of X is (b1(X) = b1(X'), Alexander duality).
  const int loopsClosed = int(gaining.size()) - joined, loopsBroken = int(losing.size()) - parts;
  using K = TopologyEventKind;
  auto record = [&](TopologyEventKind kind, int times) {
    for (int n = 0; n < times; ++n) events.push_back({step, crossing, c, grid.Node(c[0], c[1], c[2]), kind});
  };
  if (joins) {
    in.empty() ? record(K::ComponentBorn, 1) : record(K::PartsMerged, joined - 1);
    out.empty() ? record(K::CavityFilled, 1) : record(K::CavityBorn, parts - 1);
  } else {
    in.empty() ? record(K::ComponentDied, 1) : record(K::PartSplit, parts - 1);
    out.empty() ? record(K::CavityBorn, 1) : record(K::CavityOpened, joined - 1);
  }
  record(K::HandleGained, loopsClosed);
  record(K::HandleLost, loopsBroken);
  const int dInside = joins ? 1 - joined : parts - 1, dOutside = joins ? parts - 1 : 1 - joined;
  components += dInside;
  complementComponents += dOutside;
  eulerCharacteristic += (joins ? 1 : -1) * StarEulerCharacteristic(around);
}

int InsideSetTracker::State::Join(std::size_t x, bool side, const std::vector<Piece> &pieces) {
  std::vector<int> roots;
  for (const Piece &p : pieces)
    roots.push_back(p.beyondGrid ? 0 : Root(side, label[lattice.At(x, __builtin_ctz(p.positions))]));
  std::sort(roots.begin(), roots.end());
  roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
  if (roots.empty()) {
    label[x] = Labels(side).Add();
    return 0;
  }
  for (int r : roots) Labels(side).Merge(r, roots.front());  // the smallest label stays the root
  label[x] = roots.front();
  return int(roots.size());
}

int InsideSetTracker::State::Part(std::size_t x, bool side, const std::vector<Piece> &pieces) {
  const int count = int(pieces.size());
  if (count <= 1) return count;
  const std::uint32_t adjacency = side ? kN6 : kN26;
  const std::uint32_t onGrid = lattice.OnGrid(lattice.Node(x));
  if (markBase > INT_MAX - count) std::fill(mark.begin(), mark.end(), -1), markBase = 0;
  const int base = markBase;
  markBase += count;

  // One breadth-first search per piece; searches that meet become one (union-find over
  // them, the smaller frontier appended to the larger). A search of X' that reaches the
  // grid's border has reached the unbounded component and never runs out.
  UnionFind search(count);
  std::vector<std::vector<std::size_t>> frontier(count);
  std::vector<std::size_t> head(count, 0);
  std::vector<char> unbounded(count, 0);
  auto meet = [&](int a, int b) {
    a = search.Find(a), b = search.Find(b);
    if (a == b) return;
    if (frontier[a].size() - head[a] < frontier[b].size() - head[b]) std::swap(a, b);
    frontier[a].insert(frontier[a].end(), frontier[b].begin() + head[b], frontier[b].end());
    frontier[b] = {};
    head[b] = 0;
    unbounded[a] |= unbounded[b];
    search.Merge(b, a);
  };
  int outside = -1;  // a search that reached the unbounded component
  auto reachUnbounded = [&](int s) {
    unbounded[search.Find(s)] = 1;
    if (outside < 0) outside = s;
    meet(s, outside);
  };
  for (int s = 0; s < count; ++s) {
    for (std::uint32_t m = pieces[s].positions & onGrid; m; m &= m - 1) {
      const std::size_t y = lattice.At(x, __builtin_ctz(m));
      mark[y] = base + s;
      frontier[s].push_back(y);
      if (!side && lattice.OnBorder(lattice.Node(y))) reachUnbounded(s);
    }
    if (pieces[s].beyondGrid) reachUnbounded(s);
  }
  auto open = [&](int s) { return head[s] < frontier[s].size() || unbounded[s]; };
  for (;;) {
    int searching = 0;
    for (int s = 0; s < count; ++s) searching += search.Find(s) == s && open(s);
    if (searching <= 1) break;
    for (int s = 0; s < count; ++s) {
      if (search.Find(s) != s || head[s] == frontier[s].size()) continue;
      const std::size_t n = frontier[s][head[s]++];
      lattice.ForEach(n, adjacency, [&](std::size_t y) {
        if (bool(inside[y]) != side) return;  // x itself is already off this side
        if (mark[y] >= base && mark[y] < base + count) return meet(s, mark[y] - base);
        mark[y] = base + s;
        frontier[search.Find(s)].push_back(y);
        if (!side && lattice.OnBorder(lattice.Node(y))) reachUnbounded(s);
      });
    }
  }

  // Every search left is one component of side \ {x}: the open one (or the first) keeps
  // its label, each other is labelled afresh by a flood fill from its pieces.
  std::vector<int> parts;
  for (int s = 0; s < count; ++s)
    if (search.Find(s) == s) parts.push_back(s);
  int keep = parts.front();
  for (int s : parts)
    if (open(s)) keep = s;
  std::vector<std::size_t> stack;
  for (int s : parts) {
    if (s == keep) continue;
    const int fresh = Labels(side).Add();
    for (int piece = 0; piece < count; ++piece)
      if (search.Find(piece) == s)
        for (std::uint32_t m = pieces[piece].positions & onGrid; m; m &= m - 1) {
          const std::size_t y = lattice.At(x, __builtin_ctz(m));
          label[y] = fresh;
          stack.push_back(y);
        }
    while (!stack.empty()) {
      const std::size_t n = stack.back();
      stack.pop_back();
      lattice.ForEach(n, adjacency, [&](std::size_t y) {
        if (bool(inside[y]) == side && label[y] != fresh) label[y] = fresh, stack.push_back(y);
      });
    }
  }
  return int(parts.size());
}

InsideSetTracker::InsideSetTracker(const ScalarField &first, const std::function<void()> &poll)
    : state_(std::make_unique<State>(first, poll)) {}
InsideSetTracker::~InsideSetTracker() = default;

ZeroSetTopology InsideSetTracker::Topology() const {
  ZeroSetTopology t;
  t.components = state_->components;
  t.cavities = state_->complementComponents - 1;
  t.eulerCharacteristic = state_->eulerCharacteristic;
  return t;
}

std::vector<TopologyEvent> InsideSetTracker::Advance(const ScalarField &next, int step, const std::function<void()> &poll) {
  State &s = *state_;
  if (next.grid.dims != s.grid.dims || next.grid.origin != s.grid.origin || next.grid.h != s.grid.h ||
      next.values.size() != s.value.size())
    throw std::invalid_argument("InsideSetTracker: the next frame lies on another grid");
  struct Crossing {
    double at;  // fraction of the step
    std::size_t node;
    std::size_t sweep;  // TopologyEvent::sweep
  };
  std::vector<Crossing> flips;  // in node order
  for (std::size_t n = 0; n < s.value.size(); ++n) {
    if (poll && n > 0 && n % kNodesBetweenPolls == 0) poll();
    if ((s.value[n] < 0) != (next.values[n] < 0)) flips.push_back({s.value[n] / (s.value[n] - next.values[n]), n, n});
  }
  // The pieces of the flips: each flip joined to its flipped +x, +y, +z neighbours.
  UnionFind pieces(int(flips.size()));
  const std::size_t nx = std::size_t(s.grid.dims.X()), ny = std::size_t(s.grid.dims.Y()), nxy = nx * ny;
  auto index = [&](std::size_t node) {  // of a flipped node in flips, or -1
    const auto it = std::lower_bound(flips.begin(), flips.end(), node,
                                     [](const Crossing &c, std::size_t n) { return c.node < n; });
    return it != flips.end() && it->node == node ? int(it - flips.begin()) : -1;
  };
  for (int f = 0; f < int(flips.size()); ++f) {
    const std::size_t n = flips[f].node;
    const bool last[3] = {n % nx == nx - 1, n / nx % ny == ny - 1, n + nxy >= s.value.size()};
    const std::size_t offset[3] = {1, nx, nxy};
    for (int a = 0; a < 3; ++a)
      if (const int g = last[a] ? -1 : index(n + offset[a]); g >= 0) pieces.Merge(f, g);
  }
  for (int f = 0; f < int(flips.size()); ++f) flips[f].sweep = flips[pieces.Find(f)].node;
  std::sort(flips.begin(), flips.end(),
            [](const Crossing &a, const Crossing &b) { return a.at < b.at || (a.at == b.at && a.node < b.node); });
  std::vector<TopologyEvent> events;
  for (const Crossing &c : flips) {
    const std::size_t before = events.size();
    s.Flip(c.node, c.at, step, events);
    for (std::size_t e = before; e < events.size(); ++e) events[e].sweep = c.sweep;
  }
  s.value = next.values;
  return events;
}

std::vector<TopologyEvent> Events(const ScalarField &before, const ScalarField &after, int step) {
  return InsideSetTracker(before).Advance(after, step);
}

} // namespace eulermap
