// Which topology events surgery acts on (surgery_plan.h): events undone soon and nearby,
// opposite events of one step, and the grid's own features at either end of the morph are
// not cut.
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

// Cut kinds of opposite sign within one piece of a step's sign flips undo each other however
// far apart (a window between two legs opening at the bottom and closing at the top 26 cells
// above), nearest first (the gain at 0 goes with the loss at 26, not the one at 60); a merge
// and a split of one step farther apart than kUndoneCells too. Opposite events of different
// steps, or of two pieces of one step, stay for surgery, and so does a merge whose opposite is
// a birth (not a cut kind).
TEST(SurgeryPlan, OppositeEventsOfOneStepUndoEachOther) {
  using K = TopologyEventKind;
  std::vector<TopologyEvent> events = {
      EventAtStep(5, 200, K::ComponentBorn),                                                // not a cut kind
      EventAtStep(14, 0, K::HandleGained),  EventAtStep(14, 26, K::HandleLost),             // between frames
      EventAtStep(14, 60, K::HandleLost),                                                   // stays
      EventAtStep(21, 150, K::PartsMerged), EventAtStep(21, 150 + kUndoneCells + 1, K::PartSplit),  // between frames
      EventAtStep(25, 200, K::PartsMerged),                                                 // the born part joins
      EventAtStep(30, 100, K::HandleGained),                                                // stays
      EventAtStep(35, 300, K::HandleGained), EventAtStep(35, 310, K::HandleLost),           // two fronts: stay
  };
  events[events.size() - 1].sweep = 1;  // the loss at step 35 flipped with another piece of the step
  const TopologyFrame frame{-1, 1, 0, 0};
  const Topology sphere{1, 0, 2};
  const std::vector<EventCut> plan = PlanSurgery(events, frame, frame, sphere, sphere, 1.0, 40);
  const std::vector<EventCut> expected = {EventCut::Planned, EventCut::BetweenFrames, EventCut::BetweenFrames,
                                          EventCut::Planned, EventCut::BetweenFrames, EventCut::BetweenFrames,
                                          EventCut::Planned, EventCut::Planned,       EventCut::Planned,
                                          EventCut::Planned};
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

