#include "report.h"

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <sstream>

namespace eulermap {

namespace {
std::string Format(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
std::string Format(const char *fmt, ...) {
  char buffer[512];
  va_list args;
  va_start(args, fmt);
  vsnprintf(buffer, sizeof buffer, fmt, args);
  va_end(args);
  return buffer;
}
} // namespace

double MapQuality::ResolvedAnchorErrorCells() const {
  double worst = 0;
  for (const AnchorFigure &a : anchorFigures)
    if (a.Resolved()) worst = std::max(worst, a.error);
  return worst;
}

int Report::HolesCut() const {
  int n = 0;
  for (const EventSurgery &s : surgery) n += s.outcome == EventCut::Cut || s.outcome == EventCut::Collapsed;
  return n;
}

std::string Report::ToText() const {
  std::ostringstream o;
  for (const std::string &r : repairs) o << "repaired: " << r << "\n";
  o << Format("grid: %d x %d x %d nodes, cell %.6g; steps: %d; alpha: %g; threads: %d\n", gridNodes.X(),
              gridNodes.Y(), gridNodes.Z(), cellSize, steps, alpha, threads);
  o << Format("source vertices: %d; anchors: %d; placement: %s; morph: %s\n", sourceVertices, anchors,
              placement.c_str(), morphMode.c_str());
  if (!morphsTried.empty()) o << "morphs tried: " << morphsTried << "\n";
  o << Format("velocity solver: %s, %ld iterations in all, at most %d in a step, final residual at most %.2e\n",
              solver.c_str(), solverFigures.totalIterations, solverFigures.maxIterations, solverFigures.maxFinalResidual);
  if (!topologyAlongMorph.empty()) {
    auto describe = [](const TopologyFrame &t) {
      return Format("%d part%s of genus %d%s", t.components, t.components == 1 ? "" : "s", t.handles,
                    t.cavities ? Format(" with %d cavit%s", t.cavities, t.cavities == 1 ? "y" : "ies").c_str() : "");
    };
    // Noisy scans change it at many steps: the first changes and the last frame are shown.
    constexpr std::size_t kShown = 8;
    const std::size_t count = topologyAlongMorph.size();
    o << "topology along the morph: " << describe(topologyAlongMorph.front());
    for (std::size_t n = 1; n < count; ++n) {
      if (n == kShown && count > kShown + 1) {
        o << Format(" -> ... (%zu more changes)", count - kShown - 1);
        n = count - 1;
      }
      o << " -> " << describe(topologyAlongMorph[n]) << Format(" (step %d)", topologyAlongMorph[n].step + 1);
    }
    o << "\n";
  }
  o << Format("topology events: %zu, %d cut\n", topologyEvents.size(), HolesCut());
  constexpr std::size_t kListed = 40;
  for (std::size_t n = 0; n < topologyEvents.size() && n < kListed; ++n) {
    const TopologyEvent &e = topologyEvents[n];
    o << Format("  step %d: %s at (%.4g, %.4g, %.4g)", e.step + 1, Name(e.kind), e.position.X(), e.position.Y(),
                e.position.Z());
    if (n < surgery.size()) {
      const EventSurgery &s = surgery[n];
      if (s.outcome == EventCut::Cut)
        o << Format(": cut (axis from %s), %d faces removed, rim length %.4g", s.axisFromSaddle ? "a saddle of V" : "f's Hessian",
                    s.facesRemoved, s.rimLength);
      else if (s.outcome == EventCut::AwayFromSurface)
        o << Format(": not cut, the tracked surface is %.1f cells away (a part no tracked point reaches)", s.distanceCells);
      else if (s.outcome == EventCut::Undone)
        o << ": not cut, an opposite event nearby undoes it";
      else if (s.outcome == EventCut::SourceGrid)
        o << ": not cut, it removes a feature of the grid's picture of the source that the source mesh has not";
      else if (s.outcome == EventCut::TargetGrid)
        o << ": not cut, it makes a feature of the grid's picture of the target that the target mesh has not";
      else if (s.outcome == EventCut::Collapsed)
        o << Format(": the piece of the tracked surface that shrank with it removed, %d faces", s.facesRemoved);
      else if (s.outcome == EventCut::OneSheetTracked)
        o << ": not cut, only one of the sheets meeting is tracked (a part no tracked point reaches)";
    }
    o << "\n";
  }
  if (topologyEvents.size() > kListed) o << Format("  ... and %zu more\n", topologyEvents.size() - kListed);
  o << Format("cut source: %d component%s, %d boundary loop%s, Euler characteristic %d; %d vertices (%d added by "
              "surgery), %d faces\n",
              cutComponents, cutComponents == 1 ? "" : "s", cutBoundaryLoops, cutBoundaryLoops == 1 ? "" : "s",
              cutEulerCharacteristic, cutVertices, pointsAdded, cutFaces);
  if (cutPredicted)
    o << Format("a continuous map onto the target needs a cut source of %d component%s, %d boundary loop%s, Euler "
                "characteristic %d: %s\n",
                neededComponents, neededComponents == 1 ? "" : "s", neededBoundaryLoops,
                neededBoundaryLoops == 1 ? "" : "s", neededEulerCharacteristic, CutAsNeeded() ? "as built" : "NOT as built");
  else if (!cutNotChecked.empty())
    o << "the cut is not checked against a prediction: " << cutNotChecked << "\n";
  o << Format("times (s): SDF %.3f, INT %.3f, VF %.3f, DEF %.3f, total %.3f (quality measures %.3f)\n", times.sdf,
              times.interp, times.velocity, times.deform, times.Total(), times.quality);
  o << Format("map quality: on-surface %.2f%%, coverage %.2f%%, flipped area %.2f%%, longest mapped edge %.2f cells, "
              "anchor error %.2f cells, mean distortion %.3f\n",
              100 * quality.onSurfaceRate, 100 * quality.coverage, 100 * quality.flippedAreaShare,
              quality.longestEdgeCells, quality.anchorErrorCells, quality.meanDistortion);
  if (!quality.anchorFigures.empty()) {
    o << "anchors (error in cells; f0 at a, f1 at b in cells):";
    std::string far;  // anchors more than a cell off, at a tip the grid cuts short
    int count = 0;
    for (std::size_t n = 0; n < quality.anchorFigures.size(); ++n) {
      const AnchorFigure &a = quality.anchorFigures[n];
      o << Format("%s %s %.2f (%.2f, %.2f)", n ? ";" : "", a.name.c_str(), a.error, a.sourceLevel, a.targetLevel);
      if (a.error > 1 && !a.Resolved()) far += (count++ ? ", " : "") + a.name;
    }
    o << "\n";
    if (count > 0)
      o << Format("note: %s %s %s more than a cell from %s; %s on %s the grid cuts short (f0 at a or f1 at b above "
                  "%.2f cells), and an image ends where the cut tip ends. The cut is about as many cells deep at any "
                  "grid, so a finer grid shortens it only in proportion; an anchor moved off the tip avoids it. "
                  "Largest error over the anchors the grid resolves: %.2f cells\n",
                  count == 1 ? "anchor" : "anchors", far.c_str(), count == 1 ? "ends" : "end",
                  count == 1 ? "its partner" : "their partners", count == 1 ? "it lies" : "they lie",
                  count == 1 ? "a tip" : "tips", AnchorFigure::kResolvedLevel, quality.ResolvedAnchorErrorCells());
  }
  if (!quality.uncoveredParts.empty()) {
    // The largest parts, each at least 0.1% of the target; the rest counted.
    o << "uncovered parts of the target (its own frame):";
    std::size_t shown = 0;
    for (const UncoveredPart &p : quality.uncoveredParts)
      if (shown < 5 && p.share >= 0.001)
        o << Format("%s %.2f%% around (%.4g, %.4g, %.4g), radius %.3g", shown++ ? ";" : "", 100 * p.share,
                    p.centre.X(), p.centre.Y(), p.centre.Z(), p.radius);
    const std::size_t rest = quality.uncoveredParts.size() - shown;
    if (rest > 0) o << Format(shown ? "; %zu smaller" : " %zu, each under 0.1%%", rest);
    o << "\n";
  }
  o << Format("untangling: flipped area %.2f%% as tracked, %d vertices relaxed on the target, %d added where edges "
              "stretched\n",
              100 * quality.flippedBeforeUntangling, untangledVertices, stretchedSplit);
  if (!texture.empty()) o << Format("texture: %s\n", texture.c_str());
  if (peakMemoryKiB > 0) o << Format("peak memory: %.1f MiB\n", peakMemoryKiB / 1024.0);
  for (const std::string &w : warnings) o << "warning: " << w << "\n";
  return o.str();
}

} // namespace eulermap
