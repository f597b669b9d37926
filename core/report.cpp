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

const std::vector<Figure> &FigureTable() {
  using U = FigureUnit;
  using L = FigureLine;
  static const std::vector<Figure> table = {
      {"repairs", U::Count, L::None, "repairs", false, [](const Report &r) { return double(r.repairs.size()); }},
      {"warnings", U::Count, L::None, "warnings", false, [](const Report &r) { return double(r.warnings.size()); }},
      {"grid_cell_size", U::Number, L::None, "cell", false, [](const Report &r) { return r.cellSize; }},
      {"steps", U::Count, L::None, "steps", false, [](const Report &r) { return double(r.steps); }},
      {"source_vertices", U::Count, L::None, "source vertices", true, [](const Report &r) { return double(r.sourceVertices); }},
      {"anchors", U::Count, L::None, "anchors", true, [](const Report &r) { return double(r.anchors); }},
      {"topology_events", U::Count, L::None, "topology events", false, [](const Report &r) { return double(r.topologyEvents.size()); }},
      {"holes", U::Count, L::None, "holes", false, [](const Report &r) { return double(r.HolesCut()); }},
      {"cut_vertices", U::Count, L::None, "cut vertices", false, [](const Report &r) { return double(r.cutVertices); }},
      {"cut_faces", U::Count, L::None, "cut faces", false, [](const Report &r) { return double(r.cutFaces); }},
      {"cut_components", U::Count, L::None, "cut components", false, [](const Report &r) { return double(r.cutComponents); }},
      {"cut_boundary_loops", U::Count, L::None, "cut boundary loops", false, [](const Report &r) { return double(r.cutBoundaryLoops); }},
      {"cut_euler_characteristic", U::Count, L::None, "cut Euler characteristic", false,
       [](const Report &r) { return double(r.cutEulerCharacteristic); }},
      {"points_added", U::Count, L::None, "points added", false, [](const Report &r) { return double(r.pointsAdded); }},
      {"stretched_split", U::Count, L::None, "points added where edges stretched", false,
       [](const Report &r) { return double(r.stretchedSplit); }},
      {"tears_opened", U::Count, L::None, "faces removed where the map tore beside a cut", false,
       [](const Report &r) { return double(r.tearsOpened); }},
      {"time_sdf_s", U::Seconds, L::Times, "SDF", true, [](const Report &r) { return r.times.sdf; }},
      {"time_int_s", U::Seconds, L::Times, "INT", true, [](const Report &r) { return r.times.interp; }},
      {"time_vf_s", U::Seconds, L::Times, "VF", true, [](const Report &r) { return r.times.velocity; }},
      {"time_def_s", U::Seconds, L::Times, "DEF", true, [](const Report &r) { return r.times.deform; }},
      {"time_total_s", U::Seconds, L::Times, "total", true, [](const Report &r) { return r.times.Total(); }},
      {"time_quality_s", U::Seconds, L::Times, "quality measures", false, [](const Report &r) { return r.times.quality; }},
      {"solver_iterations", U::Count, L::None, "solver iterations", true,
       [](const Report &r) { return double(r.solverFigures.totalIterations); }},
      {"solver_max_step_iterations", U::Count, L::None, "most in a step", true,
       [](const Report &r) { return double(r.solverFigures.maxIterations); }},
      {"peak_memory_mib", U::Number, L::None, "peak MiB", true, [](const Report &r) { return r.peakMemoryKiB / 1024.0; }},
      {"on_surface_rate", U::Share, L::Quality, "on-surface", true, [](const Report &r) { return r.quality.onSurfaceRate; }},
      {"coverage", U::Share, L::Quality, "coverage", true, [](const Report &r) { return r.quality.coverage; }},
      {"flipped_area_share", U::Share, L::Quality, "flipped area", true, [](const Report &r) { return r.quality.flippedAreaShare; }},
      {"flipped_before_untangling", U::Share, L::None, "flipped as tracked", false,
       [](const Report &r) { return r.quality.flippedBeforeUntangling; }},
      {"longest_edge_cells", U::Cells, L::Quality, "longest mapped edge", false, [](const Report &r) { return r.quality.longestEdgeCells; }},
      {"longest_edge_share", U::Share, L::None, "longest mapped edge over the target diagonal", false,
       [](const Report &r) { return r.quality.longestEdgeShare; }},
      {"stretched_edge_share", U::Share, L::None, "longest stretched edge over the target diagonal", false,
       [](const Report &r) { return r.quality.stretchedEdgeShare; }},
      {"anchor_error_cells", U::Cells, L::Quality, "anchor error", true, [](const Report &r) { return r.quality.anchorErrorCells; }},
      {"anchor_error_resolved_cells", U::Cells, L::None, "anchor error, resolved anchors", true,
       [](const Report &r) { return r.quality.ResolvedAnchorErrorCells(); }},
      {"mean_distortion", U::Number, L::Quality, "mean distortion", false, [](const Report &r) { return r.quality.meanDistortion; }},
  };
  return table;
}

std::string Figure::Text(const Report &report) const {
  const double x = value(report);
  switch (unit) {
  case FigureUnit::Count: return Format("%.0f", x);
  case FigureUnit::Share: return Format("%.2f%%", 100 * x);
  case FigureUnit::Seconds: return Format("%.3f", x);
  case FigureUnit::Cells: return Format("%.2f cells", x);
  case FigureUnit::Number: return Format("%.3f", x);
  }
  return "";
}

namespace {
// "map quality: on-surface 99.79%, coverage ...": the figures of one line.
std::string FigureLineText(const char *title, FigureLine line, const Report &report) {
  std::string text = title;
  const char *separator = ": ";
  for (const Figure &f : FigureTable())
    if (f.line == line) text += separator + std::string(f.label) + " " + f.Text(report), separator = ", ";
  return text + "\n";
}
} // namespace

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
  if (!placementsTried.empty()) o << "placements tried: " << placementsTried << "\n";
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
        o << Format(": cut (axis from %s)%s%s, %d faces removed, rim length %.4g",
                    s.axisTurned       ? "another plane: the first axis' band was a disc or parted the surface otherwise than the event"
                    : s.axisFromSaddle ? "a saddle of V"
                                       : "f's Hessian",
                    s.narrowed ? " (without the swept gap's faces: with them the cut did otherwise than the event)" : "",
                    s.stepsLate == 0 ? ""
                                     : Format(" at step %d, when the tracked surface reached it", e.step + 1 + s.stepsLate).c_str(),
                    s.facesRemoved, s.rimLength);
      if (s.outcome == EventCut::Cut && !s.asEvent)
        o << Format("; the cut does otherwise than its event, before the cleaning: %d loops more and the Euler "
                    "characteristic %+d (a disc pair's: 2 and -2; a band's: 2 and 0)",
                    s.loopsAdded, s.eulerChange);
      else if (s.outcome == EventCut::AwayFromSurface)
        o << Format(": not cut, the tracked surface is %.1f cells away (a part no tracked point reaches)", s.distanceCells);
      else if (s.outcome == EventCut::Undone)
        o << ": not cut, an opposite event nearby undoes it";
      else if (s.outcome == EventCut::BetweenFrames)
        o << ": not cut, an opposite event of the same step and front undoes it (no frame holds the feature)";
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
  o << FigureLineText("times (s)", FigureLine::Times, *this);
  o << FigureLineText("map quality", FigureLine::Quality, *this);
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
              "stretched, %d faces removed where the map tore beside a cut, %d disc pairs' rims glued\n",
              100 * quality.flippedBeforeUntangling, untangledVertices, stretchedSplit, tearsOpened, rimsGlued);
  if (!texture.empty()) o << Format("texture: %s\n", texture.c_str());
  if (peakMemoryKiB > 0) o << Format("peak memory: %.1f MiB\n", peakMemoryKiB / 1024.0);
  for (const std::string &w : warnings) o << "warning: " << w << "\n";
  return o.str();
}

} // namespace eulermap
