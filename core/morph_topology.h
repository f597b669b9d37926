// eulermap::TrackTopology — the topology of the inside set {f(., t) < 0} along the whole
// morph, and every event that changes it (zero_set_topology.h), found before any point is
// tracked so that surgery can weigh each event against those after it (surgery_plan.h).
//
// Inputs:  the morph (morph.h), its number of steps K, a progress callback (may be empty;
//          called before each step's frame, its sign flips and its topology with the share
//          done, 0..1; it may throw to cancel)
// Outputs: frames: the topology of f(., 0) (step -1), then of each f(., t_k+1) where it
//          changed; events: every event of every step, in order (step, then flip order).
// Frames are made one at a time (Morph::Frame, Eq. 1) and dropped: memory is one frame and
// the tracker's labels, whatever K is. The tracking pass makes the frames again.
#pragma once

#include "morph.h"
#include "report.h"

#include <functional>
#include <vector>

namespace eulermap {

struct TopologyHistory {
  std::vector<TopologyFrame> frames;
  std::vector<TopologyEvent> events;
};

TopologyHistory TrackTopology(const Morph &morph, int steps, const std::function<void(double)> &progress = {});

} // namespace eulermap
