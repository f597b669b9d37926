#include "surgery.h"

#include "edge_faces.h"
#include "refine_stretched.h"
#include "union_find.h"

#include <vcg/complex/algorithms/hole.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg/complex/append.h>
#include <vcg/space/distance3.h>
#include <vcg/space/triangle3.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

namespace eulermap {

namespace {

constexpr double kOffLevelCells = 0.25;  // a tracked point this far off f = 0 has lost its level set
// A tracked edge whose chord's midpoint lies this far outside per unit of its length is not
// split. Below refine_stretched.h's kGapSag (the right-angled concave corner's 0.354): an
// edge refused now can be split at a later step, and at 0.4 the points added around the
// last holes of sphere -> ring4 at 64 cells changed its cut (11 loops for 8, 9 at 0.25).
constexpr double kOutsideChordSag = 0.25;
constexpr double kSpreadStretch = 2;  // edges stretched more than this (and long) are split anywhere
constexpr double kReachCells = 10;  // the event's crossings count within this many cells (+ hole radius)
constexpr double kTakesPartCells = 6;  // the tracked surface takes part in an event this near (+ hole radius)
constexpr double kSheetConeDegrees = 60;  // a sheet meeting another lies within this angle of the cut's axis
constexpr double kCollapsedCells = 5;  // a piece within this many cells (+ hole radius) of a dying part goes with it

bool FarFromBox(const Point3 &p, double r, const Point3 &a, const Point3 &b, const Point3 &c) {
  for (int x = 0; x < 3; ++x)
    if (std::min({a[x], b[x], c[x]}) > p[x] + r || std::max({a[x], b[x], c[x]}) < p[x] - r) return true;
  return false;
}

// The gap a step closes at an event: the nodes it sweeps into the inside set (f(., t_k) >= 0
// and f(., t_k+1) < 0) between two fronts, joined through 6-neighbours to the event's node x
// (swept itself where sheets or a hole's walls meet at the event's own step; else none, as
// where a neck pinches). A node lies between
// two fronts where, along one of the axes, the run of swept nodes through it ends at a node
// already inside at t_k on both sides. Where two sheets meet at a point (spheres merging) it
// is a few nodes around x; where flat fronts meet across a whole section (the rails of chair
// -> chair_rails growing from both legs) it is the slab between them, the section's size. A
// front that moves on alone sweeps a layer with the old inside on one side only: it is no
// gap. (Every swept node joined to x was taken once: decimated-knight -> sphere at 96 cells
// grown at centre-and-scale, the step's whole shell round the knight, and the disc pair of a
// handle gained at step 2 took 653 faces and cut the knight into 4 pieces, 35% covered.)
class Swept {
 public:
  Swept(const vcg::Point3i &x, const ScalarField &fCur, const ScalarField &fNext) : grid_(fNext.grid) {
    const Grid &g = grid_;
    const int step[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    auto swept = [&](int i, int j, int k) {
      const std::size_t n = g.Index(i, j, k);
      return fCur.values[n] >= 0 && fNext.values[n] < 0;
    };
    // Whether the run of swept nodes from (i, j, k) along d ends at a node inside at t_k.
    auto endsInside = [&](int i, int j, int k, const int *d) {
      do i += d[0], j += d[1], k += d[2];
      while (Inside(i, j, k) && swept(i, j, k));
      return Inside(i, j, k) && fCur.values[g.Index(i, j, k)] < 0;
    };
    auto between = [&](int i, int j, int k) {
      if (!Inside(i, j, k) || !swept(i, j, k)) return false;
      for (int a = 0; a < 3; ++a)
        if (endsInside(i, j, k, step[2 * a]) && endsInside(i, j, k, step[2 * a + 1])) return true;
      return false;
    };
    if (!between(x[0], x[1], x[2])) return;
    std::vector<std::size_t> stack = {g.Index(x[0], x[1], x[2])};
    nodes_.insert(stack.back());
    while (!stack.empty()) {
      const std::size_t n = stack.back();
      stack.pop_back();
      const vcg::Point3i node = g.Coordinates(n);
      const int i = node.X(), j = node.Y(), k = node.Z();
      for (const auto &d : step)
        if (between(i + d[0], j + d[1], k + d[2]) && nodes_.insert(g.Index(i + d[0], j + d[1], k + d[2])).second)
          stack.push_back(g.Index(i + d[0], j + d[1], k + d[2]));
    }
  }
  // Whether a corner of the cell holding p was swept; with `outward` (the normal of the
  // surface p lay on at t_k), only a corner on its outside. A hole's wall faces the gap it
  // closes, and a tube thinner than a cell has its far side in the same cells, facing away
  // (thin_ring -> sphere at 64 cells: the ring's hole fills, and the band took 59 faces of
  // the tube's far side too, leaving an edge of 57.5% of the target's diagonal). Sheets
  // meeting take every swept corner: the flat fronts of chair -> chair_rails, tracked a cell
  // or two behind the level set, face the gap from outside it (with the side, the membrane
  // stayed: 96 and 128 cells, edges of 6.1% and 6.0% of the diagonal).
  bool Touches(const Point3 &p, const Point3 *outward = nullptr) const {
    if (nodes_.empty()) return false;
    const Point3 c = grid_.ToGrid(p);
    const int i = int(std::floor(c.X())), j = int(std::floor(c.Y())), k = int(std::floor(c.Z()));
    for (int dz = 0; dz < 2; ++dz)
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx)
          if (Inside(i + dx, j + dy, k + dz) && nodes_.count(grid_.Index(i + dx, j + dy, k + dz)) &&
              (!outward || (grid_.Node(i + dx, j + dy, k + dz) - p) * *outward >= 0))
            return true;
    return false;
  }

 private:
  bool Inside(int i, int j, int k) const {
    return i >= 0 && j >= 0 && k >= 0 && i < grid_.dims.X() && j < grid_.dims.Y() && k < grid_.dims.Z();
  }
  const Grid &grid_;
  std::unordered_set<std::size_t> nodes_;
};

double Area(const Point3 &a, const Point3 &b, const Point3 &c) { return ((b - a) ^ (c - a)).Norm() / 2; }

// Distance s >= 0 along the unit direction d from o to triangle (a, b, c), or -1 if the
// ray misses it (Moller-Trumbore).
double RayTriangle(const Point3 &o, const Point3 &d, const Point3 &a, const Point3 &b, const Point3 &c) {
  const Point3 e1 = b - a, e2 = c - a, p = d ^ e2;
  const double det = e1 * p;
  if (std::abs(det) < 1e-30) return -1;
  const Point3 t = o - a;
  const double u = (t * p) / det;
  if (u < 0 || u > 1) return -1;
  const Point3 q = t ^ e1;
  const double v = (d * q) / det;
  if (v < 0 || u + v > 1) return -1;
  const double s = (e2 * q) / det;
  return s >= 0 ? s : -1;
}

// The point of triangle (a, b, c) nearest to p.
Point3 ClosestOnTriangle(const Point3 &p, const Point3 &a, const Point3 &b, const Point3 &c) {
  double distance;
  Point3 closest;
  vcg::TrianglePointDistance(vcg::Triangle3<double>(a, b, c), p, distance, closest);
  return closest;
}

double DistanceToTriangle(const Point3 &p, const Point3 &a, const Point3 &b, const Point3 &c) {
  return vcg::Distance(p, ClosestOnTriangle(p, a, b, c));
}

} // namespace

Surgery::Surgery(const Mesh &source, double radius, double cell, const std::vector<TopologyEvent> &events,
                 const std::vector<EventCut> &plan, bool growing)
    : radius_(radius), cell_(cell), events_(events), growing_(growing) {
  if (plan.size() != events.size()) throw std::logic_error("Surgery: one plan entry per event");
  for (std::size_t e = 0; e < events.size(); ++e) {
    EventSurgery o;
    o.event = int(e);
    o.outcome = plan[e];
    outcomes_.push_back(o);
  }
  if (source.vn != int(source.vert.size()) || source.fn != int(source.face.size()))
    throw std::logic_error("Surgery: the source has deleted vertices or faces");
  sourceVertices_ = int(source.vert.size());
  sourceFaces_ = int(source.face.size());
  for (const Vertex &v : source.vert) sourcePosition_.push_back(v.cP()), trackedAs_.push_back(trackedAs_.size());
  // Faces, the source's own boundary edges, connected components and their areas.
  EdgeFaces edges(sourceFaces_);
  UnionFind parts(sourceVertices_);
  tris_.resize(sourceFaces_);
  for (int f = 0; f < sourceFaces_; ++f) {
    Tri &t = tris_[f];
    for (int c = 0; c < 3; ++c) t.v[c] = int(vcg::tri::Index(source, source.face[f].cV(c)));
    t.root = f;
    t.bary = {Point3(1, 0, 0), Point3(0, 1, 0), Point3(0, 0, 1)};
    for (int e = 0; e < 3; ++e) {
      edges.Add(t.v[e], t.v[(e + 1) % 3], f);
      parts.Merge(t.v[e], t.v[(e + 1) % 3]);
    }
  }
  std::vector<int> componentOf(sourceVertices_, -1);
  for (Tri &t : tris_) {
    for (int e = 0; e < 3; ++e) t.border[e] = edges.Around(t.v[e], t.v[(e + 1) % 3]).size() == 1;
    int &c = componentOf[parts.Find(t.v[0])];
    if (c < 0) c = int(componentArea_.size()), componentArea_.push_back(0);
    t.component = c;
    componentArea_[c] += Area(sourcePosition_[t.v[0]], sourcePosition_[t.v[1]], sourcePosition_[t.v[2]]);
  }
}

int Surgery::PointsAdded() const {
  std::vector<char> used(sourcePosition_.size(), 0);
  for (const Tri &t : tris_)
    if (t.state == kAlive)
      for (int c = 0; c < 3; ++c) used[t.v[c]] = 1;
  return int(std::count(used.begin() + sourceVertices_, used.end(), 1));
}

std::vector<Point3> Surgery::Positions(const std::vector<Point3> &tracked) const {
  std::vector<Point3> p;
  p.reserve(trackedAs_.size());
  for (std::size_t n : trackedAs_) p.push_back(tracked[n]);
  return p;
}

bool Surgery::Acts(int k) const {
  if (!arriving_.empty()) return true;
  for (std::size_t e = next_; e < events_.size() && events_[e].step <= k; ++e)
    if (events_[e].step == k && outcomes_[e].outcome == EventCut::Planned) return true;
  return false;
}

void Surgery::Step(int k, const std::vector<Saddle> &saddles, const ScalarField &fCur, const ScalarField &fNext,
                   Tracker &tracker) {
  const std::size_t begin = next_;
  while (next_ < events_.size() && events_[next_].step <= k) ++next_;
  std::vector<Point3> position = Positions(tracker.Points());
  std::vector<std::pair<int, Point3>> cutting;  // outcomes that cut at this step, and where
  std::vector<std::size_t> acting;  // the step's planned events, then those the tracked surface is still nearing
  for (std::size_t e = begin; e < next_; ++e)
    if (outcomes_[e].outcome == EventCut::Planned) acting.push_back(e);
  acting.insert(acting.end(), arriving_.begin(), arriving_.end());
  arriving_.clear();
  for (std::size_t e : acting) {
    EventSurgery &outcome = outcomes_[e];
    const TopologyEvent &event = events_[e];
    const CutShape shape = ShapeOf(event.kind);
    const double near = kTakesPartCells * cell_ + radius_;
    // A part dying: the piece of the tracked surface that shrank with it (cut off from the
    // rest by the events before, all within kCollapsedCells of x) maps onto nothing and goes.
    if (event.kind == TopologyEventKind::ComponentDied) {
      const std::vector<int> piece = CollapsedPiece(event.position, kCollapsedCells * cell_ + radius_, position);
      for (int n : piece) tris_[n].state = outcome.event;
      outcome.outcome = piece.empty() ? EventCut::NotACutKind : EventCut::Collapsed;
      if (!piece.empty()) cutting.push_back({outcome.event, event.position});
      continue;
    }
    // 1. A cut kind, where the tracked surface takes part, now or in the steps after while it
    // comes nearer (it lags the level set where sheets meet).
    const bool arriving = outcome.outcome == EventCut::AwayFromSurface;
    const double before = outcome.distanceCells;
    if (shape != CutShape::None) outcome.distanceCells = NearestTriangle(event.position, 2 * near, position) / cell_;
    outcome.outcome = shape == CutShape::None                 ? EventCut::NotACutKind
                      : outcome.distanceCells * cell_ > near ? EventCut::AwayFromSurface
                                                              : EventCut::Cut;
    if (outcome.outcome == EventCut::AwayFromSurface && (!arriving || outcome.distanceCells < before))
      arriving_.push_back(e);
    if (outcome.outcome == EventCut::Cut) {
      outcome.stepsLate = k - event.step;
      // 2. The faces its geometry crosses (b) — where sheets meet, only if both are tracked
      // (a part grown from nothing merging with the surface leaves it as it is) — and the
      // sphere around x (a).
      const CutDirection axis = CutAxis(event, fNext, saddles);
      outcome.axisFromSaddle = axis.fromSaddle;
      bool bothSheets = true;
      // The faces cut along an axis: (b), then with reach 1 (a) and with reach 2 (c) too, joined to (b).
      auto cutAlong = [&](const Point3 &d, int reach = 2) {
        std::vector<int> faces = Crossing(event.position, d, shape, position, &bothSheets);
        if (!bothSheets) return faces;
        const std::vector<int> crossing = faces;
        if (reach >= 1)
          for (int n : InSphere(event.position, position)) faces.push_back(n);
        // (c) where the step closes a gap at x, at the event's own step, the cut grows over
        // the faces that lie where the step swept it (Swept): sheets meeting (discs), or the
        // walls of a hole that closes (a handle lost as a band), those facing the gap. A neck
        // that pinches sweeps nothing in at x, and its band stays as (a) and (b) make it.
        if (reach >= 2 && outcome.stepsLate == 0) {
          const Swept gap(event.node, fCur, fNext);
          const std::vector<int> grown = Spread(
              faces,
              [&](const Point3 &p) {
                if (shape == CutShape::Discs) return gap.Touches(p);
                const Point3 outward = fCur.Gradient(p);
                return gap.Touches(p, &outward);
              },
              position);
          faces.insert(faces.end(), grown.begin(), grown.end());
        }
        // Only what is joined to (b) through the cut's own faces, corner to corner: a piece of
        // (a) or (c) apart from both discs (or the band) lies on another layer of the tracked
        // surface, and cutting it would open a hole that no event calls for.
        return JoinedTo(crossing, faces);
      };
      std::vector<int> faces = cutAlong(axis.axis);
      // The cut does to the surface what the event does to the inside set (islands that Clean
      // removes left out): two loops more; the Euler characteristic two less for a disc pair
      // (two discs out) and the same for a band (an annulus out); a part more where one
      // splits, none elsewhere (a handle's band never parts the surface).
      // Where the axis' disc pair does otherwise, the pair without the swept gap's faces (c),
      // where that does: where flat fronts meet across a whole section the gap's faces can
      // reach other cuts' rims (the H of stretchers under table_h grown from table at 64
      // cells: 14 756 faces whose removal left the loops and the Euler characteristic as they
      // were, cut 1/4/-2 where 1/6/-4). Not a band: the lining of a hole that closes across
      // a whole section is a wall the step sweeps flat, and a band without it leaves the wall
      // folded (shelf -> sphere inflated at 64 cells, its levels' tunnels: 0.00% -> 7.91%
      // flipped).
      // Where the axis' band does otherwise, the band of fewest faces along another plane
      // (cut_axis.h, BandPlanes) that does; else, of those that part the surface as the event
      // does and hold a loop (no disc), the fewest. At a handle's root the Hessian read one
      // cell wide may point along the wall the handle leaves (cup -> ring1 at 64 cells: the
      // band ran round the cup's whole wall, rim length 4.64, cut 2/4/-2 where 1/4/-2 was
      // predicted); where a window fills between thin parts its planes cut the parts elsewhere
      // (stool3 -> sphere at 64 cells: holes of 6 faces for two of three windows, cut 1/4/-6
      // where 1/6/-4).
      const int splits = event.kind == TopologyEventKind::PartSplit ? 1 : 0;
      if (bothSheets && !faces.empty() && shape != CutShape::None) {
        const SurfaceFigures before = Figures({});
        auto asEvent = [&](const SurfaceFigures &after) {
          return after.parts - before.parts == splits && after.loops - before.loops == 2 &&
                 after.euler - before.euler == (shape == CutShape::Discs ? -2 : 0);
        };
        // A cut with its figures; those of the one kept go to the log where it does otherwise.
        auto does = [&](const std::vector<int> &cut, const SurfaceFigures &after, bool exactly) {
          return exactly ? asEvent(after) : after.parts - before.parts == splits && Euler(cut) <= 0;
        };
        SurfaceFigures after = Figures(faces);
        if (shape == CutShape::Discs && !asEvent(after))
          if (std::vector<int> narrower = cutAlong(axis.axis, 1); !narrower.empty())
            if (const SurfaceFigures figures = Figures(narrower); asEvent(figures))
              faces = std::move(narrower), after = figures, outcome.narrowed = true;
        // The other planes' bands, fewest faces first (the first plane on a tie): the first that
        // does is the one wanted, and those after it are not counted (Figures reads the whole
        // surface: counting all 16 planes' bands took table -> chair at 48 cells from 28.5 to
        // 32.2 s a map).
        std::vector<std::vector<int>> others;
        for (const bool exactly : {true, false}) {
          if (shape != CutShape::Band || does(faces, after, exactly)) break;
          if (others.empty()) {
            for (const Point3 &d : BandPlanes(event, fNext))
              if (std::vector<int> other = cutAlong(d); !other.empty()) others.push_back(std::move(other));
            std::stable_sort(others.begin(), others.end(),
                             [](const std::vector<int> &a, const std::vector<int> &b) { return a.size() < b.size(); });
          }
          for (const std::vector<int> &other : others)
            if (const SurfaceFigures figures = Figures(other); does(other, figures, exactly)) {
              faces = other, after = figures, outcome.axisTurned = true;
              break;
            }
          if (outcome.axisTurned) break;
        }
        outcome.asEvent = asEvent(after);
        outcome.loopsAdded = after.loops - before.loops, outcome.eulerChange = after.euler - before.euler;
      }
      if (!bothSheets) {
        outcome.outcome = EventCut::OneSheetTracked;
      } else {
        for (int n : faces)
          if (tris_[n].state == kAlive) tris_[n].state = outcome.event;
        cutting.push_back({outcome.event, event.position});
      }
    }
  }
  // 3. Clean the rims; 4. refine them as they open.
  if (!cutting.empty()) Clean(position, cutting), cut_ = true;
  Refine(position, fNext, tracker);
}

EdgeFaces Surgery::AliveEdges() const {
  EdgeFaces edges(tris_.size());
  AliveEdges(edges);
  return edges;
}

void Surgery::AliveEdges(EdgeFaces &edges) const {
  edges.Clear();
  for (int n = 0; n < int(tris_.size()); ++n)
    if (tris_[n].state == kAlive)
      for (int e = 0; e < 3; ++e) edges.Add(tris_[n].v[e], tris_[n].v[(e + 1) % 3], n);
}

double Surgery::NearestTriangle(const Point3 &x, double limit, const std::vector<Point3> &position) const {
  double nearest = limit;
  for (const Tri &t : tris_) {
    if (t.state != kAlive) continue;
    const Point3 &a = position[t.v[0]], &b = position[t.v[1]], &c = position[t.v[2]];
    if (!FarFromBox(x, nearest, a, b, c)) nearest = std::min(nearest, DistanceToTriangle(x, a, b, c));
  }
  return nearest;
}

std::vector<int> Surgery::CollapsedPiece(const Point3 &x, double reach, const std::vector<Point3> &position) const {
  int seed = -1;
  double nearest = reach;
  for (int n = 0; n < int(tris_.size()); ++n) {
    const Tri &t = tris_[n];
    if (t.state != kAlive) continue;
    const Point3 &a = position[t.v[0]], &b = position[t.v[1]], &c = position[t.v[2]];
    if (FarFromBox(x, nearest, a, b, c)) continue;
    const double d = DistanceToTriangle(x, a, b, c);
    if (d < nearest) nearest = d, seed = n;
  }
  if (seed < 0) return {};
  const EdgeFaces faces = AliveEdges();
  std::vector<char> seen(tris_.size(), 0);
  std::vector<int> piece, stack = {seed};
  seen[seed] = 1;
  while (!stack.empty()) {
    const int n = stack.back();
    stack.pop_back();
    piece.push_back(n);
    const Tri &t = tris_[n];
    for (int c = 0; c < 3; ++c)
      if (vcg::Distance(position[t.v[c]], x) > reach) return {};  // reaches beyond: not collapsed
    for (int e = 0; e < 3; ++e)
      for (int m : faces.Around(t.v[e], t.v[(e + 1) % 3]))
        if (!seen[m]) seen[m] = 1, stack.push_back(m);
  }
  return piece;
}

std::vector<int> Surgery::InSphere(const Point3 &x, const std::vector<Point3> &position) const {
  std::vector<int> cut;
  for (int n = 0; n < int(tris_.size()); ++n) {
    const Tri &t = tris_[n];
    if (t.state != kAlive) continue;
    const Point3 &a = position[t.v[0]], &b = position[t.v[1]], &c = position[t.v[2]];
    const double r2 = radius_ * radius_;
    if (vcg::SquaredDistance(a, x) <= r2 || vcg::SquaredDistance(b, x) <= r2 || vcg::SquaredDistance(c, x) <= r2) {
      cut.push_back(n);
      continue;
    }
    if (!FarFromBox(x, radius_, a, b, c) && DistanceToTriangle(x, a, b, c) <= radius_) cut.push_back(n);
  }
  // All faces around a corner inside the sphere.
  std::vector<char> inside(position.size(), 0);
  for (std::size_t n = 0; n < position.size(); ++n) inside[n] = vcg::SquaredDistance(position[n], x) <= radius_ * radius_;
  for (int n = 0; n < int(tris_.size()); ++n) {
    const Tri &t = tris_[n];
    if (t.state == kAlive && (inside[t.v[0]] || inside[t.v[1]] || inside[t.v[2]])) cut.push_back(n);
  }
  return cut;
}

std::vector<int> Surgery::Crossing(const Point3 &o, const Point3 &d, CutShape shape, const std::vector<Point3> &position,
                                   bool *bothSheets) const {
  const double reach = kReachCells * cell_ + radius_;
  std::vector<int> cut;
  if (shape == CutShape::Discs) {
    // Two sheets face each other along the axis: on each side, the nearest face the line
    // (x, axis) pierces, else (the line passes by a sheet that meets it at a tip: a rail of
    // chair -> chair_rails growing from a leg at 64 cells lies 0.37 cells from x, and the
    // line first meets the surface 17 cells away) the face within kSheetConeDegrees of the
    // axis whose point nearest to x is nearest over the cosine of its angle to the axis;
    // and the faces within the sphere's radius of that point that are joined to that face
    // through faces within the radius: one disc of this sheet. Another layer of the tracked
    // surface passing within the radius (a fold, or the sheet curving back) is not the
    // sheet meeting the other here, and a disc cut from it opens a hole that no event
    // calls for (a fold beside the cap growing round an outer torus of sphere -> ring4 at
    // 64 cells).
    const double cone = std::cos(kSheetConeDegrees * M_PI / 180);
    for (double side : {1.0, -1.0}) {
      int hit = -1;
      double nearest = reach;
      for (int n = 0; n < int(tris_.size()); ++n) {
        const Tri &t = tris_[n];
        if (t.state != kAlive) continue;
        const double s = RayTriangle(o, d * side, position[t.v[0]], position[t.v[1]], position[t.v[2]]);
        if (s >= 0 && s < nearest) nearest = s, hit = n;
      }
      Point3 q = o + d * (side * nearest);
      const bool pierced = hit >= 0;
      double best = reach / cone;
      for (int n = 0; !pierced && n < int(tris_.size()); ++n) {
        const Tri &t = tris_[n];
        if (t.state != kAlive) continue;
        const Point3 &a = position[t.v[0]], &b = position[t.v[1]], &c = position[t.v[2]];
        if (FarFromBox(o, std::min(best, reach), a, b, c)) continue;
        const Point3 p = ClosestOnTriangle(o, a, b, c);
        const double dist = vcg::Distance(p, o), along = (p - o) * d * side;
        if (dist > reach || along <= 0 || along < cone * dist) continue;
        if (const double key = dist * dist / along; key < best) best = key, hit = n, q = p;
      }
      if (hit < 0) {
        *bothSheets = false;
        continue;
      }
      EdgeFaces near;  // the faces within the radius of q, by edge
      for (int n = 0; n < int(tris_.size()); ++n) {
        const Tri &t = tris_[n];
        if (t.state != kAlive) continue;
        const Point3 &a = position[t.v[0]], &b = position[t.v[1]], &c = position[t.v[2]];
        if (n == hit || (!FarFromBox(q, radius_, a, b, c) && DistanceToTriangle(q, a, b, c) <= radius_))
          for (int e = 0; e < 3; ++e) near.Add(t.v[e], t.v[(e + 1) % 3], n);
      }
      for (int n : ConnectedFrom(hit, near)) cut.push_back(n);
    }
    return cut;
  }
  // A neck pinches across the plane normal to the axis: the loop of faces crossing it
  // around x, from the nearest such face along faces that share a crossing edge, however
  // far the loop reaches. The tracked surface lags the level set, and the lining of a slot
  // that zips shut (chair_slats -> chair: from the seat up to the event under the top rail)
  // is squeezed into the plane along the slot's whole length: a loop cut short at some
  // distance from x leaves a strip, a hole with one rim where a band has two.
  auto side = [&](int p) { return (position[p] - o) * d >= 0; };
  auto crosses = [&](const Tri &t) { return side(t.v[0]) != side(t.v[1]) || side(t.v[1]) != side(t.v[2]); };
  int seed = -1;
  double nearest = reach;
  EdgeFaces faces;  // crossing faces, by edge
  for (int n = 0; n < int(tris_.size()); ++n) {
    const Tri &t = tris_[n];
    if (t.state != kAlive || !crosses(t)) continue;
    for (int e = 0; e < 3; ++e)
      if (side(t.v[e]) != side(t.v[(e + 1) % 3])) faces.Add(t.v[e], t.v[(e + 1) % 3], n);
    const Point3 &a = position[t.v[0]], &b = position[t.v[1]], &c = position[t.v[2]];
    if (FarFromBox(o, nearest, a, b, c)) continue;
    if (const double dist = DistanceToTriangle(o, a, b, c); dist < nearest) nearest = dist, seed = n;
  }
  if (seed < 0) return cut;
  return ConnectedFrom(seed, faces);
}

int Surgery::Euler(const std::vector<int> &faces) const {
  std::vector<int> corners;
  std::vector<std::pair<int, int>> edges;
  for (int n : faces)
    for (int e = 0; e < 3; ++e) {
      const int a = tris_[n].v[e], b = tris_[n].v[(e + 1) % 3];
      corners.push_back(a);
      edges.push_back({std::min(a, b), std::max(a, b)});
    }
  auto distinct = [](auto &items) {
    std::sort(items.begin(), items.end());
    return int(std::unique(items.begin(), items.end()) - items.begin());
  };
  return distinct(corners) - distinct(edges) + int(faces.size());
}

Surgery::SurfaceFigures Surgery::Figures(const std::vector<int> &cut) const {
  std::vector<char> kept(tris_.size(), 0);
  for (int n = 0; n < int(tris_.size()); ++n) kept[n] = tris_[n].state == kAlive;
  for (int n : cut) kept[n] = 0;
  EdgeFaces faces(tris_.size());
  for (int n = 0; n < int(tris_.size()); ++n)
    if (kept[n])
      for (int e = 0; e < 3; ++e) faces.Add(tris_[n].v[e], tris_[n].v[(e + 1) % 3], n);
  // Pieces, and the islands among them: a rim and less than kIslandShare of the component's area.
  UnionFind pieces(int(tris_.size()));
  std::vector<char> rimmed(tris_.size(), 0);
  for (int n = 0; n < int(tris_.size()); ++n)
    if (kept[n])
      for (int e = 0; e < 3; ++e) {
        const EdgeFaces::Faces around = faces.Around(tris_[n].v[e], tris_[n].v[(e + 1) % 3]);
        for (int m : around) pieces.Merge(n, m);
        if (around.size() == 1 && !tris_[n].border[e]) rimmed[n] = 1;
      }
  std::unordered_map<int, std::pair<double, bool>> piece;  // per piece: its area on the source, whether it has a rim
  for (int n = 0; n < int(tris_.size()); ++n)
    if (kept[n]) {
      const Tri &t = tris_[n];
      auto &[area, rim] = piece[pieces.Find(n)];
      area += Area(sourcePosition_[t.v[0]], sourcePosition_[t.v[1]], sourcePosition_[t.v[2]]);
      rim = rim || rimmed[n];
    }
  auto island = [&](int n) {
    const auto &[area, rim] = piece.at(pieces.Find(n));
    return rim && area < kIslandShare * componentArea_[tris_[n].component];
  };
  // Counted as Clean leaves them: a corner where the surface touches itself (faces around it in
  // two fans, joined by no edge) counts once a fan, and rims that touch there as two loops:
  // V counts fans, and the loops are the boundary edges' cycles, E - V + C of their graph.
  SurfaceFigures figures;
  UnionFind fans(3 * int(tris_.size()));  // corner c of face n: 3 n + c, joined across the edges at it
  UnionFind rims(int(sourcePosition_.size()));
  std::vector<char> onRim(sourcePosition_.size(), 0);
  for (int n = 0; n < int(tris_.size()); ++n) {
    if (!kept[n] || island(n)) continue;
    const Tri &t = tris_[n];
    ++figures.euler;  // F
    if (pieces.Find(n) == n) ++figures.parts;
    for (int e = 0; e < 3; ++e) {
      const int a = t.v[e], b = t.v[(e + 1) % 3];
      const EdgeFaces::Faces around = faces.Around(a, b);
      if (around[0] == n) --figures.euler;  // E, each edge once
      for (int m : around)
        for (int c = 0; c < 3; ++c) {
          if (tris_[m].v[c] == a) fans.Merge(3 * n + e, 3 * m + c);
          if (tris_[m].v[c] == b) fans.Merge(3 * n + (e + 1) % 3, 3 * m + c);
        }
      if (around.size() == 1) {
        ++figures.loops;  // + E of the rims' graph
        rims.Merge(a, b);
        onRim[a] = onRim[b] = 1;
      }
    }
  }
  for (int n = 0; n < int(tris_.size()); ++n)
    if (kept[n] && !island(n))
      for (int c = 0; c < 3; ++c) figures.euler += fans.Find(3 * n + c) == 3 * n + c;  // V, once a fan
  for (std::size_t v = 0; v < onRim.size(); ++v)
    if (onRim[v]) figures.loops += (rims.Find(int(v)) == int(v)) - 1;  // + C - V of the rims' graph
  return figures;
}

std::vector<int> Surgery::Spread(const std::vector<int> &seeds, const std::function<bool(const Point3 &)> &near,
                                 const std::vector<Point3> &position) const {
  const EdgeFaces faces = AliveEdges();
  std::unordered_set<int> seen(seeds.begin(), seeds.end());
  std::vector<int> stack(seeds.begin(), seeds.end()), grown;
  while (!stack.empty()) {
    const Tri &t = tris_[stack.back()];
    stack.pop_back();
    for (int e = 0; e < 3; ++e)
      for (int m : faces.Around(t.v[e], t.v[(e + 1) % 3])) {
        const Tri &u = tris_[m];
        if (!seen.insert(m).second || !near(position[u.v[0]]) || !near(position[u.v[1]]) || !near(position[u.v[2]]))
          continue;
        grown.push_back(m);
        stack.push_back(m);
      }
  }
  return grown;
}

std::vector<int> Surgery::JoinedTo(const std::vector<int> &seeds, const std::vector<int> &faces) const {
  std::unordered_map<int, std::vector<int>> around;  // point -> the faces of `faces` at it
  std::unordered_set<int> unique;
  for (int n : faces)
    if (unique.insert(n).second)
      for (int c = 0; c < 3; ++c) around[tris_[n].v[c]].push_back(n);
  std::unordered_set<int> seen(seeds.begin(), seeds.end());
  std::vector<int> stack(seen.begin(), seen.end()), joined;
  while (!stack.empty()) {
    const int n = stack.back();
    stack.pop_back();
    joined.push_back(n);
    for (int c = 0; c < 3; ++c)
      for (int m : around[tris_[n].v[c]])
        if (seen.insert(m).second) stack.push_back(m);
  }
  return joined;
}

std::vector<int> Surgery::ConnectedFrom(int seed, const EdgeFaces &faces) const {
  std::vector<int> piece;
  std::unordered_set<int> seen = {seed};
  std::vector<int> stack = {seed};
  while (!stack.empty()) {
    const int n = stack.back();
    stack.pop_back();
    piece.push_back(n);
    const Tri &t = tris_[n];
    for (int e = 0; e < 3; ++e)
      for (int m : faces.Around(t.v[e], t.v[(e + 1) % 3]))
        if (seen.insert(m).second) stack.push_back(m);
  }
  return piece;
}

void Surgery::Clean(const std::vector<Point3> &position, const std::vector<std::pair<int, Point3>> &cutting) {
  // Faces the cleaning removes go to the nearest event that cut at this step.
  auto remove = [&](Tri &t) {
    const Point3 centre = (position[t.v[0]] + position[t.v[1]] + position[t.v[2]]) / 3;
    double best = 1e300;
    for (const auto &c : cutting)
      if (vcg::Distance(c.second, centre) < best) best = vcg::Distance(c.second, centre), t.state = c.first;
  };
  EdgeFaces faces(tris_.size());  // refilled every round
  for (int round = 0; round < 1000; ++round) {
    AliveEdges(faces);
    // The round's rims, looked up once: edge e of alive face n (not the source's border) with
    // no alive face across sets bit e of rims[n].
    std::vector<std::uint8_t> rims(tris_.size(), 0);
    for (int n = 0; n < int(tris_.size()); ++n)
      if (const Tri &t = tris_[n]; t.state == kAlive)
        for (int e = 0; e < 3; ++e)
          if (!t.border[e] && faces.Around(t.v[e], t.v[(e + 1) % 3]).size() == 1) rims[n] |= std::uint8_t(1 << e);
    auto rim = [&](int n, int e) { return (rims[n] >> e) & 1; };
    bool changed = false;
    // Ears: two or more edges on a rim.
    for (int n = 0; n < int(tris_.size()); ++n)
      if (tris_[n].state == kAlive && rim(n, 0) + rim(n, 1) + rim(n, 2) >= 2) remove(tris_[n]), changed = true;
    if (changed) continue;
    // Non-manifold vertices on a rim: keep the largest fan of faces around them.
    std::unordered_map<int, std::vector<int>> around;
    for (int n = 0; n < int(tris_.size()); ++n)
      if (tris_[n].state == kAlive)
        for (int e = 0; e < 3; ++e)
          if (rim(n, e)) around[tris_[n].v[e]], around[tris_[n].v[(e + 1) % 3]];
    for (int n = 0; n < int(tris_.size()); ++n)
      if (tris_[n].state == kAlive)
        for (int c = 0; c < 3; ++c) {
          auto it = around.find(tris_[n].v[c]);
          if (it != around.end()) it->second.push_back(n);
        }
    UnionFind fans(int(tris_.size()));
    for (auto &[v, fan] : around) {
      for (int n : fan) {
        const Tri &t = tris_[n];
        for (int e = 0; e < 3; ++e)
          if (t.v[e] == v || t.v[(e + 1) % 3] == v)
            for (int m : faces.Around(t.v[e], t.v[(e + 1) % 3])) fans.Merge(n, m);
      }
      std::unordered_map<int, int> size;
      for (int n : fan) ++size[fans.Find(n)];
      if (size.size() < 2) continue;
      const int largest = std::max_element(size.begin(), size.end(), [](auto &a, auto &b) { return a.second < b.second; })->first;
      for (int n : fan)
        if (tris_[n].state == kAlive && fans.Find(n) != largest) remove(tris_[n]), changed = true;
    }
    if (changed) continue;
    // Islands: pieces with a rim and less than kIslandShare of their component's area.
    std::vector<int> piece(tris_.size(), -1), stack;
    for (int seed = 0; seed < int(tris_.size()); ++seed) {
      if (tris_[seed].state != kAlive || piece[seed] >= 0) continue;
      std::vector<int> members;
      bool hasRim = false;
      double area = 0;
      piece[seed] = seed;
      stack.push_back(seed);
      while (!stack.empty()) {
        const int n = stack.back();
        stack.pop_back();
        members.push_back(n);
        const Tri &t = tris_[n];
        area += Area(sourcePosition_[t.v[0]], sourcePosition_[t.v[1]], sourcePosition_[t.v[2]]);
        for (int e = 0; e < 3; ++e) {
          hasRim = hasRim || rim(n, e);
          for (int m : faces.Around(t.v[e], t.v[(e + 1) % 3]))
            if (piece[m] < 0) piece[m] = seed, stack.push_back(m);
        }
      }
      if (hasRim && area < kIslandShare * componentArea_[tris_[seed].component]) {
        for (int n : members) remove(tris_[n]);
        changed = true;
      }
    }
    if (!changed) break;
  }
}

void Surgery::Refine(std::vector<Point3> &position, const ScalarField &fNext, Tracker &tracker) {
  if (!SplitsStretched()) return;  // nothing cut or grown yet: the source's faces stay
  const double limit = kSplitCells * cell_;
  std::vector<Point3> born;  // tracked positions of the points added at this step
  EdgeFaces faces(tris_.size());  // refilled every pass
  std::vector<char> onRim;        // per point
  for (int pass = 0; pass < 4; ++pass) {
    auto longEdge = [&](const Tri &t, int e) { return vcg::Distance(position[t.v[e]], position[t.v[(e + 1) % 3]]) > limit; };
    // Only long edges are split: without one the pass has nothing to do, and the faces
    // around every edge are not gathered for the rims (Table 1 row 2, cut at its 11th step:
    // DEF 0.30 -> 0.18 s, most steps after the cut having no long edge).
    if (std::none_of(tris_.begin(), tris_.end(),
                     [&](const Tri &t) { return t.state == kAlive && (longEdge(t, 0) || longEdge(t, 1) || longEdge(t, 2)); }))
      break;
    if (cut_) {
      AliveEdges(faces);
      onRim.assign(position.size(), 0);
      for (const Tri &t : tris_)
        if (t.state == kAlive)
          for (int e = 0; e < 3; ++e)
            if (!t.border[e] && faces.Around(t.v[e], t.v[(e + 1) % 3]).size() == 1) onRim[t.v[e]] = onRim[t.v[(e + 1) % 3]] = 1;
    }
    // Torn: long, and longer than kSpreadStretch times on the source (a surface growing into
    // a part of the target).
    auto torn = [&](const Tri &t, int e) {
      const int a = t.v[e], b = t.v[(e + 1) % 3];
      return longEdge(t, e) && vcg::Distance(position[a], position[b]) > kSpreadStretch * vcg::Distance(sourcePosition_[a], sourcePosition_[b]);
    };
    auto atRim = [&](const Tri &t) { return onRim[t.v[0]] || onRim[t.v[1]] || onRim[t.v[2]]; };  // only when cut_
    // Long edges of faces at a rim, and torn edges anywhere while growing, get a midpoint, unless an end has
    // lost its level set: the part of the surface it followed vanished without a cut (a
    // handle lost that the plan leaves uncut, a membrane gone at once), so the pull-back
    // leaves it off f = 0 and every point put between lands on the other end (ring1 ->
    // ring2 at 64 cells: 200 such points, and 30000 points added after them in 6 steps
    // until the budget ran out).
    auto onLevel = [&](int p) { return std::abs(fNext.Value(position[p])) <= kOffLevelCells * cell_; };
    // Nor where the chord runs outside, more than kOutsideChordSag of its length off the
    // surface: the ends lie on two rims of an opening that the cut did not reach (sphere ->
    // ring3 at 64 cells: the middle hole opens 6 steps before the end, and 30000 points
    // landed on one end or the other of chords across it).
    auto alongSurface = [&](int a, int b) {
      return fNext.Value((position[a] + position[b]) / 2) <= kOutsideChordSag * vcg::Distance(position[a], position[b]);
    };
    std::unordered_map<std::uint64_t, int> midpoint;
    for (const Tri &t : tris_)
      if (t.state == kAlive)
        for (int e = 0; e < 3; ++e) {
          const int a = t.v[e], b = t.v[(e + 1) % 3];
          if (((cut_ && atRim(t) && longEdge(t, e)) || (growing_ && torn(t, e))) && onLevel(a) && onLevel(b) && alongSurface(a, b))
            midpoint[EdgeFaces::Key(a, b)] = -1;
        }
    if (midpoint.empty() || PointsAdded() + int(midpoint.size()) > kAddedPerVertex * sourceVertices_) break;  // the budget
    for (auto &[key, id] : midpoint) {
      const int a = int(key >> 32), b = int(key & 0xffffffffu);
      id = int(sourcePosition_.size());
      sourcePosition_.push_back((sourcePosition_[a] + sourcePosition_[b]) / 2);
      parents_.push_back({a, b});
      trackedAs_.push_back(tracker.Points().size() + born.size());
      born.push_back(PullBack(fNext, (position[a] + position[b]) / 2, 0));
      position.push_back(born.back());
    }
    // Split every face with a marked edge: 1 -> 2, 3 or 4 faces. Corners are (point,
    // barycentric coordinates in the parent).
    const int count = int(tris_.size());
    for (int n = 0; n < count; ++n) {
      if (tris_[n].state != kAlive) continue;
      const Tri parent = tris_[n];
      int mid[3], marked = 0;
      for (int e = 0; e < 3; ++e) {
        auto it = midpoint.find(EdgeFaces::Key(parent.v[e], parent.v[(e + 1) % 3]));
        mid[e] = it == midpoint.end() ? -1 : it->second;
        marked += mid[e] >= 0;
      }
      if (marked == 0) continue;
      struct Corner {
        int point;
        Point3 b;
      };
      const Corner V[3] = {{parent.v[0], Point3(1, 0, 0)}, {parent.v[1], Point3(0, 1, 0)}, {parent.v[2], Point3(0, 0, 1)}};
      Corner M[3];
      for (int e = 0; e < 3; ++e) M[e] = {mid[e], (V[e].b + V[(e + 1) % 3].b) / 2};
      std::vector<std::array<Corner, 3>> children;
      if (marked == 3) {
        children = {{V[0], M[0], M[2]}, {M[0], V[1], M[1]}, {M[2], M[1], V[2]}, {M[0], M[1], M[2]}};
      } else if (marked == 1) {
        const int e = mid[0] >= 0 ? 0 : mid[1] >= 0 ? 1 : 2;
        children = {{V[e], M[e], V[(e + 2) % 3]}, {M[e], V[(e + 1) % 3], V[(e + 2) % 3]}};
      } else {
        // Unmarked edge u = (a, b), c opposite; marked edges (b, c) and (c, a).
        const int u = mid[0] < 0 ? 0 : mid[1] < 0 ? 1 : 2;
        const Corner &a = V[u], &b = V[(u + 1) % 3], &c = V[(u + 2) % 3];
        const Corner &mbc = M[(u + 1) % 3], &mca = M[(u + 2) % 3];
        children = {{mca, mbc, c}};
        // The quad (a, b, mbc, mca): the shorter diagonal in the tracked surface.
        if (vcg::Distance(position[a.point], position[mbc.point]) < vcg::Distance(position[b.point], position[mca.point]))
          children.push_back({a, b, mbc}), children.push_back({a, mbc, mca});
        else
          children.push_back({a, b, mca}), children.push_back({b, mbc, mca});
      }
      tris_[n].state = kSplit;
      for (std::array<Corner, 3> &child : children) {
        // Keep the parent's orientation (positive determinant of the barycentric coordinates).
        const Point3 &p = child[0].b, &q = child[1].b, &r = child[2].b;
        if ((p ^ q) * r < 0) std::swap(child[1], child[2]);
        Tri t = parent;
        t.state = kAlive;
        for (int c = 0; c < 3; ++c) {
          t.v[c] = child[c].point;
          t.bary[c] = parent.bary[0] * child[c].b[0] + parent.bary[1] * child[c].b[1] + parent.bary[2] * child[c].b[2];
        }
        // An edge on the parent's edge e (both ends with coordinate e+2 zero) keeps its border flag.
        for (int e = 0; e < 3; ++e) {
          t.border[e] = false;
          for (int pe = 0; pe < 3; ++pe)
            if (child[e].b[(pe + 2) % 3] == 0 && child[(e + 1) % 3].b[(pe + 2) % 3] == 0) t.border[e] = parent.border[pe];
        }
        tris_.push_back(t);
      }
    }
  }
  tracker.Add(born, 0);  // born on f = 0
}

std::vector<Point3> Surgery::Build(Mesh &source, const std::vector<Point3> &tracked, Mesh &cut,
                                   std::vector<EventSurgery> &outcomes) const {
  outcomes = outcomes_;
  cut.Clear();
  vcg::tri::Append<Mesh, Mesh>::MeshCopy(cut, source, false, false);
  vcg::tri::UpdateBounding<Mesh>::Box(cut);
  const std::vector<Point3> position = Positions(tracked);
  bool changed = int(tris_.size()) != sourceFaces_;
  for (int f = 0; f < sourceFaces_ && !changed; ++f) changed = tris_[f].state != kAlive;
  if (!changed) return std::vector<Point3>(position.begin(), position.begin() + sourceVertices_);

  // The report: per cutting event, faces removed and rim length on the source. A rim edge
  // goes to the event of the nearest removed face.
  std::vector<std::pair<Point3, int>> removed;  // source-side centroid, outcome
  for (const Tri &t : tris_)
    if (t.state >= 0) {
      ++outcomes[t.state].facesRemoved;
      removed.push_back({(sourcePosition_[t.v[0]] + sourcePosition_[t.v[1]] + sourcePosition_[t.v[2]]) / 3, t.state});
    }
  const EdgeFaces alive = AliveEdges();
  for (const Tri &t : tris_)
    if (t.state == kAlive)
      for (int e = 0; e < 3; ++e) {
        if (t.border[e] || alive.Around(t.v[e], t.v[(e + 1) % 3]).size() != 1 || removed.empty()) continue;
        const Point3 &a = sourcePosition_[t.v[e]], &b = sourcePosition_[t.v[(e + 1) % 3]];
        int hole = 0;
        double best = 1e300;
        for (const auto &r : removed)
          if (vcg::SquaredDistance(r.first, (a + b) / 2) < best) best = vcg::SquaredDistance(r.first, (a + b) / 2), hole = r.second;
        outcomes[hole].rimLength += vcg::Distance(a, b);
      }

  // Vertex data of the added points: interpolated from the edge they split.
  const int points = int(sourcePosition_.size());
  std::vector<Point3> normal(points);
  std::vector<vcg::Color4b> colour(points);
  std::vector<vcg::TexCoord2d> tex(points);
  std::vector<double> quality(points);
  for (int v = 0; v < sourceVertices_; ++v)
    normal[v] = source.vert[v].cN(), colour[v] = source.vert[v].cC(), tex[v] = source.vert[v].cT(), quality[v] = source.vert[v].cQ();
  for (int n = sourceVertices_; n < points; ++n) {
    const int a = parents_[n - sourceVertices_][0], b = parents_[n - sourceVertices_][1];
    normal[n] = (normal[a] + normal[b]).Normalize();
    colour[n].lerp(colour[a], colour[b], 0.5f);
    tex[n] = tex[a];
    tex[n].U() = (tex[a].U() + tex[b].U()) / 2;
    tex[n].V() = (tex[a].V() + tex[b].V()) / 2;
    quality[n] = (quality[a] + quality[b]) / 2;
  }
  // Points in use: the source's vertices that are not left without faces, the added
  // points that some face uses.
  std::vector<char> used(points, 0), usedBefore(sourceVertices_, 0);
  for (int f = 0; f < sourceFaces_; ++f)
    for (int c = 0; c < 3; ++c) usedBefore[tris_[f].v[c]] = 1;
  for (const Tri &t : tris_)
    if (t.state == kAlive)
      for (int c = 0; c < 3; ++c) used[t.v[c]] = 1;
  vcg::tri::Allocator<Mesh>::AddVertices(cut, points - sourceVertices_);
  for (int n = sourceVertices_; n < points; ++n) {
    Vertex &v = cut.vert[n];
    v.P() = sourcePosition_[n], v.N() = normal[n], v.C() = colour[n], v.T() = tex[n], v.Q() = quality[n];
  }
  // Faces: the source's that stay as they are, then the new ones with the data of the
  // source face they lie in (wedge texture coordinates interpolated).
  for (int f = 0; f < sourceFaces_; ++f)
    if (tris_[f].state != kAlive) vcg::tri::Allocator<Mesh>::DeleteFace(cut, cut.face[f]);
  int added = 0;
  for (std::size_t n = sourceFaces_; n < tris_.size(); ++n) added += tris_[n].state == kAlive;
  auto face = vcg::tri::Allocator<Mesh>::AddFaces(cut, added);
  for (std::size_t n = sourceFaces_; n < tris_.size(); ++n) {
    const Tri &t = tris_[n];
    if (t.state != kAlive) continue;
    const Face &root = source.face[t.root];
    face->ImportData(root);
    for (int c = 0; c < 3; ++c) {
      face->V(c) = &cut.vert[t.v[c]];
      vcg::TexCoord2d w = root.cWT(0);
      w.U() = w.V() = 0;
      for (int r = 0; r < 3; ++r) w.U() += t.bary[c][r] * root.cWT(r).U(), w.V() += t.bary[c][r] * root.cWT(r).V();
      face->WT(c) = w;
    }
    ++face;
  }
  std::vector<Point3> images;
  for (int n = 0; n < points; ++n) {
    const bool keep = n < sourceVertices_ ? used[n] || !usedBefore[n] : used[n];
    if (keep) images.push_back(position[n]);
    else vcg::tri::Allocator<Mesh>::DeleteVertex(cut, cut.vert[n]);
  }
  vcg::tri::Allocator<Mesh>::CompactEveryVector(cut);
  vcg::tri::UpdateTopology<Mesh>::FaceFace(cut);
  vcg::tri::UpdateBounding<Mesh>::Box(cut);
  vcg::tri::UpdateNormal<Mesh>::PerFaceNormalized(cut);
  return images;
}

int FillHoles(Mesh &cut, Mesh &filled) {
  filled.Clear();
  vcg::tri::Append<Mesh, Mesh>::MeshCopy(filled, cut, false, false);
  vcg::tri::UpdateTopology<Mesh>::FaceFace(filled);
  const int n = vcg::tri::Hole<Mesh>::EarCuttingFill<vcg::tri::MinimumWeightEar<Mesh>>(filled, INT_MAX, false);
  vcg::tri::Allocator<Mesh>::CompactEveryVector(filled);
  vcg::tri::UpdateTopology<Mesh>::FaceFace(filled);
  vcg::tri::UpdateBounding<Mesh>::Box(filled);
  vcg::tri::UpdateNormal<Mesh>::PerVertexNormalizedPerFace(filled);
  return n;
}

} // namespace eulermap
