// eulermap::Measure, eulermap::Events, eulermap::InsideSetTracker — the topology of the
// inside set {f < 0} of a field on the grid, and the events that change it between two
// frames, decided exactly from f itself (DESIGN.md: the notes on topology events).
//
// The digital object. X is the set of grid nodes with f < 0; its complement X' holds the
// nodes with f >= 0 and, by convention, everything beyond the grid. X is taken with
// 6-adjacency (nodes one grid edge apart) and X' with 26-adjacency (nodes of one cell),
// the pair (6, 26) of digital topology (T. Y. Kong, A. Rosenfeld, "Digital topology:
// introduction and survey", CVGIP 48(3), 1989). Why this pair: along a grid edge whose ends
// are both negative the trilinear interpolant of f is negative all the way, so two nodes of
// X that this adjacency connects are connected inside the interpolant's own inside set; the
// same holds for every square and cube whose corners are all in X (convex combinations of
// negative values). Two diagonal nodes of X are not connected by it, and the interpolant
// gives no such guarantee between them.
//
// Measure (global, exact):
//   components  6-components of X, by flood fill;
//   cavities    26-components of X' that do not reach the grid's border (bounded
//               components of the complement in space; Betti number b2 of X);
//   chi         the Euler characteristic of the cubical complex K(X) made of the nodes of
//               X and the grid's edges, squares and cubes whose corners all lie in X:
//               chi = #nodes - #edges + #squares - #cubes (the Euler-Poincare formula for
//               cubical complexes; T. Kaczynski, K. Mischaikow, M. Mrozek, "Computational
//               Homology", Springer 2004). K(X) is the complex whose connectivity is X's
//               6-adjacency and whose complement's connectivity is 26-adjacency (the all-corners
//               complex would be the wrong one for 26-adjacent X: there a diagonal pair is
//               one component, but no edge of the complex joins it);
//   handles     b1 = components + cavities - chi (chi = b0 - b1 + b2 for a compact set in
//               space), which is also the sum of the genera of X's boundary surfaces, so the
//               total genus of the zero set.
//
// Events (exact, located): the nodes whose sign changes between two frames are flipped one
// at a time, in the order in which they cross zero when f moves linearly from one frame to
// the next (each node's crossing fraction f_before / (f_before - f_after); node index on a
// tie). Under the 0-anchor linear blend the frames' f is linear in t, so this is the order
// of the continuous morph itself. A flip that is a simple point of the set it is applied to
// changes nothing: by G. Bertrand, G. Malandain, "A new characterization of three-dimensional
// simple points", Pattern Recognition Letters 15(2), 1994, for the pair (6, 26) a node x is
// simple iff T6(x, X) = 1 (6-components of X in the 18-neighbourhood of x, x excluded, that
// contain a 6-neighbour of x) and T26(x, X') = 1 (26-components of X' in the 26-neighbourhood,
// x excluded). At every other flip, with the pieces T6 and T26 count around x:
//   the side gaining x  (X or X', each with its adjacency) joins the components its pieces
//               lie in (union-find over component labels): pieces in k distinct components
//               merge k into one, and each further piece closes a loop through x;
//   the side losing x   may fall apart: one breadth-first search per piece, run in turns,
//               until all but one have met or run out (a search that runs out has found a
//               component on its own, labelled afresh); each piece beyond the first in a
//               part was on a loop through x, now broken;
//   a loop of X' is a handle of X as much as a loop of X (b1(X) = b1(X'), Alexander duality),
//   so: components of X merged / split / born (no piece) / died, cavities born (X' split or
//   a lone X' node) / filled / opened (X' components joined), handles gained (loops
//   closed) and lost (loops broken). One flip may do several at once; a handle gained and
//   one lost at the same node leave the Betti numbers as they were but are still reported.
//   chi is kept up to date from the cells of K that x completes or breaks (the 26 cells
//   having x as a corner), and Topology() reports the figures Measure would.
// Each unit change is one TopologyEvent at the flipped node, so the events of a step add up
// to the difference of Measure between its two frames.
#pragma once

#include "field.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace eulermap {

// A 6-component of X.
struct InsideComponent {
  std::size_t nodes = 0;  // its size in nodes
  Point3 centroid = Point3(0, 0, 0);  // mean of its nodes, world coordinates
};

struct ZeroSetTopology {
  int components = 0;           // b0 of X
  int cavities = 0;             // b2 of X
  int eulerCharacteristic = 0;  // chi(K(X))
  std::vector<InsideComponent> parts;  // one per component, in the storage order of their first node
  // b1 of X: the total genus of the zero set's surfaces.
  int Handles() const { return components + cavities - eulerCharacteristic; }
};

// in:  f on its grid
// out: the topology of X = {nodes with f < 0} (header), with each component's size and centroid
ZeroSetTopology Measure(const ScalarField &f);

enum class TopologyEventKind {
  ComponentBorn,  // components +1: a node of X with no 6-neighbour in X (a minimum of f crosses 0)
  ComponentDied,  // components -1: the last node of a component leaves X
  PartsMerged,    // components -1: x joins two components of X
  PartSplit,      // components +1: a component of X parts at x
  HandleGained,   // handles +1
  HandleLost,     // handles -1
  CavityBorn,     // cavities +1: X encloses a piece of the complement, or x empties inside a solid
  CavityFilled,   // cavities -1: x was the last node of a cavity
  CavityOpened,   // cavities -1: x joins a cavity to the outside or to another cavity
};

// in: a kind; out: its name, as the log and the tests print it
const char *Name(TopologyEventKind kind);

struct TopologyEvent {
  int step = 0;
  double crossing = 0;  // where in the step x crosses 0, f linear between the frames: 0..1
  vcg::Point3i node = vcg::Point3i(0, 0, 0);  // the flipped node x
  Point3 position = Point3(0, 0, 0);          // x in world coordinates
  TopologyEventKind kind = TopologyEventKind::ComponentBorn;
  // The piece of the step's sign flips, joined through 6-neighbours, that x belongs to (a
  // node of it): a front that crosses a gap within one step flips one piece.
  std::size_t sweep = 0;
};

// Changes of the three numbers (after - before).
struct TopologyChange {
  int components = 0, handles = 0, cavities = 0;
  bool operator==(const TopologyChange &o) const {
    return components == o.components && handles == o.handles && cavities == o.cavities;
  }
};

// in:  an event kind / a list of events / two measures
// out: its unit change / the sum of their changes / after - before
TopologyChange Effect(TopologyEventKind kind);
TopologyChange Effect(const std::vector<TopologyEvent> &events);
TopologyChange Difference(const ZeroSetTopology &before, const ZeroSetTopology &after);

// Follows X over the frames f(., t_0), f(., t_1), ...: component labels of X and of X'
// are kept from frame to frame, so a step costs its flips (and searches at non-simple
// ones), not a labelling of the whole grid.
class InsideSetTracker {
 public:
  // in: the first frame; poll (may be empty): called every few milliseconds while the
  //     first frame is labelled (a pass or two over the grid), may throw to cancel
  explicit InsideSetTracker(const ScalarField &first, const std::function<void()> &poll = {});
  ~InsideSetTracker();

  // in:  the next frame (same grid, else std::invalid_argument), the step's number; poll
  //      (may be empty): called every kNodesBetweenPolls nodes while the sign flips are
  //      found (interrupt.h), may throw to cancel
  // out: the step's events, in the order of their flips; the tracker now holds `next`'s X
  std::vector<TopologyEvent> Advance(const ScalarField &next, int step, const std::function<void()> &poll = {});

  // The current X's components, cavities and chi (parts left empty), as Measure gives them.
  ZeroSetTopology Topology() const;

 private:
  struct State;  // X, its labels and their union-find, in zero_set_topology.cpp
  std::unique_ptr<State> state_;
};

// in:  two frames on one grid, the step's number
// out: the events between them (InsideSetTracker(before).Advance(after, step))
std::vector<TopologyEvent> Events(const ScalarField &before, const ScalarField &after, int step);

// in:  a 3x3x3 neighbourhood: bit (dx+1) + 3 (dy+1) + 9 (dz+1) set iff that node is in X
//      (the centre's bit is ignored)
// out: whether the centre is a simple point for the pair (6, 26): T6 = 1 and T26 = 1
bool IsSimple(std::uint32_t neighbourhood);

} // namespace eulermap
