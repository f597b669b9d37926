#include "surgery_plan.h"

#include "cut_axis.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace eulermap {

namespace {

// The feature an event creates (+1) or destroys (-1): 0 components, 1 handles, 2 cavities.
struct Feature {
  int betti = 0;
  int sign = 0;
};

Feature FeatureOf(TopologyEventKind kind) {
  switch (kind) {
    case TopologyEventKind::ComponentBorn:
    case TopologyEventKind::PartSplit: return {0, +1};
    case TopologyEventKind::ComponentDied:
    case TopologyEventKind::PartsMerged: return {0, -1};
    case TopologyEventKind::HandleGained: return {1, +1};
    case TopologyEventKind::HandleLost: return {1, -1};
    case TopologyEventKind::CavityBorn: return {2, +1};
    case TopologyEventKind::CavityFilled:
    case TopologyEventKind::CavityOpened: return {2, -1};
  }
  return {};
}

// Marks `excess` events of the given feature and sign as `role`, among those still Planned,
// from the front (the source's end) or the back (the target's).
void MarkExcess(const std::vector<TopologyEvent> &events, std::vector<EventCut> &plan, int betti, int sign, int excess,
                bool fromFront, EventCut role) {
  const int n = int(events.size());
  for (int i = 0; i < n && excess > 0; ++i) {
    const int e = fromFront ? i : n - 1 - i;
    const Feature f = FeatureOf(events[e].kind);
    if (plan[e] == EventCut::Planned && f.betti == betti && f.sign == sign) plan[e] = role, --excess;
  }
}

// Whether surgery cuts at an event of this kind (cut_axis.h: two sheets meeting, or a neck
// pinching); births, deaths and cavities are not cut.
bool CutKind(TopologyEventKind kind) { return ShapeOf(kind) != CutShape::None; }

// BetweenFrames: the cut-kind events of opposite sign of one feature within each piece of a
// step's sign flips, paired off nearest first.
void PairWithinSteps(const std::vector<TopologyEvent> &events, std::vector<EventCut> &plan, int betti) {
  struct Candidate {
    double distance;
    int a, b;
  };
  std::vector<Candidate> pairs;
  for (int a = 0; a < int(events.size()); ++a)
    for (int b = 0; b < int(events.size()); ++b) {
      const Feature f = FeatureOf(events[a].kind), g = FeatureOf(events[b].kind);
      const bool oneFront = events[a].step == events[b].step && events[a].sweep == events[b].sweep;
      if (oneFront && f.betti == betti && g.betti == betti && f.sign > 0 && g.sign < 0 && CutKind(events[a].kind) &&
          CutKind(events[b].kind))
        pairs.push_back({vcg::Distance(events[a].position, events[b].position), a, b});
    }
  std::sort(pairs.begin(), pairs.end(), [](const Candidate &x, const Candidate &y) {
    return std::tie(x.distance, x.a, x.b) < std::tie(y.distance, y.a, y.b);
  });
  for (const Candidate &c : pairs)
    if (plan[c.a] == EventCut::Planned && plan[c.b] == EventCut::Planned) plan[c.a] = plan[c.b] = EventCut::BetweenFrames;
}

} // namespace

std::vector<EventCut> PlanSurgery(const std::vector<TopologyEvent> &events, const TopologyFrame &first,
                                  const TopologyFrame &last, const Topology &sourceMesh, const Topology &targetMesh,
                                  double cell, int steps) {
  std::vector<EventCut> plan(events.size(), EventCut::Planned);
  PairWithinSteps(events, plan, 0);
  PairWithinSteps(events, plan, 1);
  // Undone: each event with the nearest open opposite one close enough in place and time.
  const double reach = kUndoneCells * cell;
  const int window = std::max(1, int(std::lround(kUndoneTime * steps)));
  std::vector<int> open;  // events not paired yet, in time order
  for (int e = 0; e < int(events.size()); ++e) {
    if (plan[e] != EventCut::Planned) continue;
    const Feature f = FeatureOf(events[e].kind);
    int best = -1;
    double nearest = reach;
    for (int o : open) {
      const Feature g = FeatureOf(events[o].kind);
      if (g.betti != f.betti || g.sign != -f.sign || events[e].step - events[o].step > window) continue;
      const double d = vcg::Distance(events[e].position, events[o].position);
      if (d <= nearest) nearest = d, best = o;
    }
    if (best < 0) {
      open.push_back(e);
      continue;
    }
    plan[e] = plan[best] = EventCut::Undone;
    open.erase(std::find(open.begin(), open.end(), best));
  }
  // The grids' own features: f0's beyond the source mesh's go first, f1's beyond the target's last.
  MarkExcess(events, plan, 0, -1, first.components - sourceMesh.components, true, EventCut::SourceGrid);
  MarkExcess(events, plan, 1, -1, first.handles - sourceMesh.Genus(), true, EventCut::SourceGrid);
  MarkExcess(events, plan, 0, +1, last.components - targetMesh.components, false, EventCut::TargetGrid);
  MarkExcess(events, plan, 1, +1, last.handles - targetMesh.Genus(), false, EventCut::TargetGrid);
  return plan;
}

} // namespace eulermap
