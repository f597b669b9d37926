// eulermap::PlanSurgery — which topology events of the morph the tracked surface is cut at
// (surgery.h acts on them), decided over the whole morph (morph_topology.h) before tracking.
//
// Every event creates or destroys one feature of {f < 0}: a component (born or split off /
// died or merged), a handle (gained / lost) or a cavity (born / filled or opened). What a
// continuous map onto the target needs is the net change from the source mesh to the target
// mesh (topology.h, NeededCut). Surgery acts on the events that make up that change and
// passes over:
//   BetweenFrames  a cut kind (handle gained or lost, parts merged or split) undone by an
//               opposite one of the same step and the same piece of its sign flips
//               (TopologyEvent::sweep), however far apart: no frame the tracker sees holds
//               the feature, and one front made and unmade it. A flat front crosses a gap
//               within one step: the legs of an inflated table meet along their whole length,
//               the window between two legs opening at the bottom and closing at the top 26
//               cells above (table -> chair at 96 cells); cut, each such pair left four loops
//               the target does not explain. Events of other pieces of the step are other
//               fronts (a scan's hand meeting its head while a foot parts from a leg). Within
//               a piece, the nearest pairs first.
//   Undone      an event undone by an opposite one (the same kind of feature created then
//               destroyed, or destroyed then created) within kUndoneCells and kUndoneTime of
//               the morph. A part about a cell thick breaks up in digital noise (a bunny's ears
//               at 64 cells: holes punch through, pieces split off and vanish within a few
//               steps, 116 events where the mesh changes nothing), and a dent or a neck that
//               forms and fills again changes nothing either. Cutting at them leaves holes a
//               continuous map does not need. Pairs are taken in time order, each event with
//               the nearest open opposite one.
//   SourceGrid  f0's inside set has more components or handles than the source mesh (parts
//               thinner than about two cells: gaps in a thin sheet look like handles): the
//               first events left that remove the excess are the grid's picture catching up
//               with the mesh, not a change of the surface.
//   TargetGrid  the same at the other end, f1's inside set against the target mesh: the
//               last events left that create the excess (a cow's legs broken at 64 cells).
// A grid that shows fewer features than a mesh has (a handle thinner than a cell, parts
// that intersect each other) cannot be helped here: the pipeline then does not check the cut.
#pragma once

#include "report.h"
#include "topology.h"

#include <vector>

namespace eulermap {

constexpr double kUndoneCells = 8;    // an event and its opposite this near (grid cells) ...
constexpr double kUndoneTime = 0.15;  // ... and this near in t (a share of the morph) undo each other

// in:  events: every event of the morph, in order (TopologyHistory::events); first, last:
//      the topology of f(., 0) and f(., 1); sourceMesh, targetMesh: the meshes' own topology
//      (topology.h, MeasureTopology); cell: the grid cell (world units); steps: K
// out: per event, EventCut::Planned (surgery acts on it) or BetweenFrames / Undone / SourceGrid /
//      TargetGrid
std::vector<EventCut> PlanSurgery(const std::vector<TopologyEvent> &events, const TopologyFrame &first,
                                  const TopologyFrame &last, const Topology &sourceMesh, const Topology &targetMesh,
                                  double cell, int steps);

} // namespace eulermap
