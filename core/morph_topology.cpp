#include "morph_topology.h"

namespace eulermap {

TopologyHistory TrackTopology(const Morph &morph, int steps, const std::function<void(double)> &progress) {
  TopologyHistory history;
  ScalarField f;
  morph.Frame(0, f);
  InsideSetTracker insideSet(f);
  auto frame = [&](int step) {
    const ZeroSetTopology t = insideSet.Topology();
    return TopologyFrame{step, t.components, t.Handles(), t.cavities};
  };
  history.frames.push_back(frame(-1));
  // The host hears from it before each of a step's three pieces (the frame, the sign flips,
  // the topology of the new inside set): each is a pass over the grid (at 256^3 nodes a step
  // took 2.5 s under load between two calls).
  auto poll = [&](int k) {
    if (progress) progress(double(k) / steps);
  };
  for (int k = 0; k < steps; ++k) {
    poll(k);
    morph.Frame(double(k + 1) / steps, f);
    poll(k);
    const std::vector<TopologyEvent> events = insideSet.Advance(f, k);
    if (events.empty()) continue;
    poll(k);
    history.events.insert(history.events.end(), events.begin(), events.end());
    const TopologyFrame now = frame(k), &last = history.frames.back();
    if (now.components != last.components || now.handles != last.handles || now.cavities != last.cavities)
      history.frames.push_back(now);
  }
  return history;
}

} // namespace eulermap
