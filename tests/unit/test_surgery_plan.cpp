// Which topology events surgery acts on (surgery_plan.h): events undone soon and nearby,
// the grid's own features at either end of the morph, and opposite events beyond the net
// change are not cut.
#include "core/surgery_plan.h"

#include <gtest/gtest.h>

#include <vector>

using namespace eulermap;

namespace {

// An event at step `step`, `cells` cells along x from the origin (cell 1).
TopologyEvent EventAtStep(int step, double cells, TopologyEventKind kind) {
  TopologyEvent e;
  e.step = step;
  e.position = Point3(cells, 0, 0);
  e.kind = kind;
  return e;
}

} // namespace

// Undone pairs: a piece splitting off and dying 2 steps later nearby, a handle gained and
// lost again; an event with no opposite one near in place and time stays for surgery.
TEST(SurgeryPlan, EventsUndoneSoonNearbyAreNotCut) {
  using K = TopologyEventKind;
  const std::vector<TopologyEvent> events = {
      EventAtStep(3, 0, K::PartSplit),     EventAtStep(5, 2, K::ComponentDied),  // undone
      EventAtStep(10, 30, K::HandleGained), EventAtStep(11, 31, K::HandleLost),  // undone
      EventAtStep(12, 60, K::HandleGained),                                      // stays
      EventAtStep(20, 31, K::HandleGained),  // the handle there was undone already: stays
  };
  const TopologyFrame first{-1, 1, 0, 0}, last{39, 1, 2, 0};
  const Topology sphere{1, 0, 2}, genus2{1, 0, -2};
  const std::vector<EventCut> plan = PlanSurgery(events, first, last, sphere, genus2, 1.0, 40);
  const std::vector<EventCut> expected = {EventCut::Undone, EventCut::Undone,  EventCut::Undone,
                                          EventCut::Undone, EventCut::Planned, EventCut::Planned};
  EXPECT_EQ(plan, expected);
}

// Cut kinds of opposite sign left beyond the net change cancel, whatever their distance:
// a window opening at the bottom and closing at the top 26 cells above within one step, a
// merge and a split farther apart than kUndoneCells; nearest in steps first (the gain at
// step 30 goes with the loss at step 31, not the one at step 20). A part born from nothing
// is not cut, so the merge that joins it to the surface stays.
TEST(SurgeryPlan, OppositeEventsBeyondTheNetChangeCancel) {
  using K = TopologyEventKind;
  const std::vector<TopologyEvent> events = {
      EventAtStep(5, 200, K::ComponentBorn),                                               // not a cut kind
      EventAtStep(14, 0, K::HandleGained),  EventAtStep(14, 26, K::HandleLost),            // cancelled
      EventAtStep(20, 100, K::HandleGained),                                               // the net change
      EventAtStep(21, 150, K::PartsMerged), EventAtStep(22, 150 + kUndoneCells + 1, K::PartSplit),  // cancelled
      EventAtStep(25, 200, K::PartsMerged),                                                // the born part joins
      EventAtStep(30, 50, K::HandleGained), EventAtStep(31, 80, K::HandleLost),            // cancelled
  };
  const TopologyFrame first{-1, 1, 0, 0}, last{39, 1, 1, 0};
  const Topology sphere{1, 0, 2}, torus{1, 0, 0};
  const std::vector<EventCut> plan = PlanSurgery(events, first, last, sphere, torus, 1.0, 40);
  const std::vector<EventCut> expected = {EventCut::Planned,   EventCut::Cancelled, EventCut::Cancelled,
                                          EventCut::Planned,   EventCut::Cancelled, EventCut::Cancelled,
                                          EventCut::Planned,   EventCut::Cancelled, EventCut::Cancelled};
  EXPECT_EQ(plan, expected);
}

// The grids' own features: f0's inside set has 2 handles the source mesh (a sphere) has not,
// so the first 2 handles lost are the grid catching up; f1's has 3 parts where the target
// mesh has 1, so the last 2 splits are the grid breaking it. The events between stay.
TEST(SurgeryPlan, TheGridsOwnFeaturesAreNotCut) {
  using K = TopologyEventKind;
  const std::vector<TopologyEvent> events = {
      EventAtStep(1, 0, K::HandleLost),   EventAtStep(2, 20, K::HandleLost), EventAtStep(15, 40, K::HandleLost),
      EventAtStep(20, 60, K::PartSplit), EventAtStep(38, 80, K::PartSplit), EventAtStep(39, 100, K::PartSplit),
  };
  const TopologyFrame first{-1, 1, 2, 0}, last{39, 3, 1, 0};
  const Topology sphere{1, 0, 2}, torus{1, 0, 0};
  const std::vector<EventCut> plan = PlanSurgery(events, first, last, sphere, torus, 1.0, 40);
  const std::vector<EventCut> expected = {EventCut::SourceGrid, EventCut::SourceGrid, EventCut::Planned,
                                          EventCut::Planned,    EventCut::TargetGrid, EventCut::TargetGrid};
  EXPECT_EQ(plan, expected);
}

