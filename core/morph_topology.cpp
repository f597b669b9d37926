#include "morph_topology.h"

namespace eulermap {

TopologyHistory TrackTopology(const Morph &morph, int steps, const std::function<void(double)> &progress) {
  // The host hears from it before each pass over the grid (each step's frame, its sign
  // flips and its topology), while each frame is made (its array filled: AssignPolling), while
  // the first one is labelled, and while the sign flips are found.
  auto poll = [&](int k) {
    if (progress) progress(double(k) / steps);
  };
  TopologyHistory history;
  ScalarField f;
  // Each frame is made with an Interrupt that reports while its array is filled and warped
  // (384^3: 56.6 M nodes, a second between the polls around it).
  auto makeFrame = [&](int frame, int k) {  // f(., t_frame), reported as step k
    const HeldThrow reporting([&] { poll(k); });
    morph.Frame(double(frame) / steps, f, reporting.interrupt());
    reporting.Rethrow();
  };
  makeFrame(0, 0);
  InsideSetTracker insideSet(f, [&] { poll(0); });
  auto frame = [&](int step) {
    const ZeroSetTopology t = insideSet.Topology();
    return TopologyFrame{step, t.components, t.Handles(), t.cavities};
  };
  history.frames.push_back(frame(-1));
  for (int k = 0; k < steps; ++k) {
    poll(k);
    makeFrame(k + 1, k);
    poll(k);
    const std::vector<TopologyEvent> events = insideSet.Advance(f, k, [&] { poll(k); });
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
