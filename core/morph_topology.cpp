#include "morph_topology.h"

#include <exception>

namespace eulermap {

TopologyHistory TrackTopology(const Morph &morph, int steps, const std::function<void(double)> &progress) {
  // The host hears from it before each pass over the grid (each step's frame, its sign
  // flips and its topology), while the first frame is made (its array filled: AssignPolling)
  // and labelled, and while the sign flips are found.
  auto poll = [&](int k) {
    if (progress) progress(double(k) / steps);
  };
  TopologyHistory history;
  ScalarField f;
  std::exception_ptr thrown;  // by progress while the first frame is made: Stop() never throws
  morph.Frame(0, f, Interrupt([&] {
    try {
      poll(0);
      return true;
    } catch (...) {
      thrown = std::current_exception();
      return false;
    }
  }));
  if (thrown) std::rethrow_exception(thrown);
  InsideSetTracker insideSet(f, [&] { poll(0); });
  auto frame = [&](int step) {
    const ZeroSetTopology t = insideSet.Topology();
    return TopologyFrame{step, t.components, t.Handles(), t.cavities};
  };
  history.frames.push_back(frame(-1));
  for (int k = 0; k < steps; ++k) {
    poll(k);
    morph.Frame(double(k + 1) / steps, f);
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
