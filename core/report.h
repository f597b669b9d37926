// eulermap::Report — every number users read (timings, solver figures, topology events and their cuts,
// map quality) in one type, printed the same way by the MeshLab log, the tests and
// the benchmark (DESIGN.md: style). Its numbers are one table (FigureTable()): their names,
// units and where they appear drive the log's quality and time lines, the figures
// pymeshlab returns and the benchmark's row.
#pragma once

#include "mesh.h"
#include "zero_set_topology.h"

#include <cmath>
#include <string>
#include <vector>

namespace eulermap {

// Per-stage wall-clock seconds, named as the paper's Table 1.
struct StageTimes {
  double sdf = 0;     // SDF: f0, f1 on the grid
  double interp = 0;  // INT: morph frames f(., t_k), anchor interpolation, warps
  double velocity = 0;  // VF: velocity fields V_k
  double deform = 0;  // DEF: advection and pull-back of the tracked points, topology events, surgery
  double quality = 0;   // measuring the map (not in the paper's table)
  double Total() const { return sdf + interp + velocity + deform; }
};

struct SolverFigures {
  long totalIterations = 0;
  int maxIterations = 0;       // largest count in one step
  double maxFinalResidual = 0; // largest relative residual at the end of a step
};

// A part of the target that the mapped surface does not come near: a cluster of the
// coverage samples left uncovered (MapQuality::coverage; quality.h, Coverage).
struct UncoveredPart {
  Point3 centre;      // mean of its samples, in the target's own frame
  double share = 0;   // its share of all the samples (about its share of the target's area)
  double radius = 0;  // largest distance of its samples from `centre`
};

// One anchor pair's figures, in grid cells. The levels tell whether the grid resolves the
// anchor's points: at a sharp tip its zero level set (trilinear) passes inside the tip, and
// the point lies off it, outside. Such a tip is cut short by about the same number of cells
// at any grid, and the image of a_i ends where the cut tip ends: on the Table 1 rows, the
// anchors with both levels within kResolvedLevel end within 0.4 cells of b_i; those at tips
// (levels 0.18-0.6) up to 3.3 cells away. The report names those more than a cell off.
struct AnchorFigure {
  static constexpr double kResolvedLevel = 0.15;
  std::string name;
  double error = 0;        // |F(a_i) - b_i|
  double sourceLevel = 0;  // f0(a_i), trilinear
  double targetLevel = 0;  // f1(b_i) (b_i placed), trilinear
  bool Resolved() const { return std::abs(sourceLevel) <= kResolvedLevel && std::abs(targetLevel) <= kResolvedLevel; }
};

// Quality of the map F: M0 -> M1 (thresholds in DESIGN.md / the tests).
struct MapQuality {
  double onSurfaceRate = 0;     // share of tracked images within 0.5% of the target's diagonal
                                // from the target, before the final projection onto it
  double coverage = 0;          // share of uniform target samples within 2% of the diagonal
                                // from the mapped surface
  std::vector<UncoveredPart> uncoveredParts;  // where the other samples lie, largest first
  double flippedAreaShare = 0;  // area share of mapped faces facing against the target
  double flippedBeforeUntangling = 0;  // the same, of the map as tracked (before untangle.h)
  double longestEdgeCells = 0;  // longest mapped edge, in grid cells
  double longestEdgeShare = 0;  // the same, over the target's bounding-box diagonal
  double stretchedEdgeShare = 0;  // the same of the edges the map stretches (quality.h, LongestStretchedEdge)
  Point3 stretchedEdgeAt{0, 0, 0};  // that edge's midpoint, on the target (its own frame)
  double anchorErrorCells = 0;  // largest |F(a_i) - b_i|, in grid cells (0 without anchors)
  std::vector<AnchorFigure> anchorFigures;  // per anchor pair, in order
  // The largest error over the anchors the grid resolves (AnchorFigure::Resolved); 0 if none.
  double ResolvedAnchorErrorCells() const;
  double meanDistortion = 0;    // mean per-vertex distortion (vertex quality of the cut layer)
};

// What surgery did at one topology event (surgery_plan.h decides which it acts on, surgery.h
// and cut_axis.h how).
enum class EventCut {
  Planned,          // surgery acts on it from its step (surgery_plan.h); one of the next five after
  Cut,              // the tracked surface was cut there
  Collapsed,        // a part dying: the piece of the tracked surface that shrank with it was removed
  NotACutKind,      // a part or cavity born or dying, a cavity filled or opened: no sheet meets or parts
  AwayFromSurface,  // no tracked triangle within 6 cells + the hole radius, at its step or as it came nearer
                    // (an untracked part's event)
  OneSheetTracked,  // sheets meet, but one side has no tracked face (a part grown from nothing merging)
  BetweenFrames,    // an opposite event of the same step and front undid it: no frame holds the feature (surgery_plan.h)
  Undone,           // an opposite event nearby soon undid it (surgery_plan.h)
  SourceGrid,       // f0's inside set has a feature the source mesh has not; this removed it
  TargetGrid,       // f1's inside set has a feature the target mesh has not; this made it
};
struct EventSurgery {
  int event = 0;              // index into Report::topologyEvents
  EventCut outcome = EventCut::NotACutKind;
  double distanceCells = 0;   // from the event to the nearest tracked triangle, in cells (cut kinds only)
  bool axisFromSaddle = false;  // the cut's axis came from a saddle of V (else from f's Hessian)
  bool axisTurned = false;      // a band along another plane (cut_axis.h, BandPlanes; surgery.h, step 2)
  bool narrowed = false;        // a disc pair without the swept gap's faces (surgery.h, step 2 (c))
  bool asEvent = true;          // the cut adds two loops and changes the Euler characteristic as its event does (Cut only)
  int loopsAdded = 0, eulerChange = 0;  // what it did instead (where not asEvent), before the cleaning
  int facesRemoved = 0;       // faces of the tracked surface removed (Cut only)
  double rimLength = 0;       // length of the boundary left, world units (Cut only)
  int stepsLate = 0;          // steps after the event's own that the tracked surface reached it (Cut only)
};

// The topology of the inside set {f(., t) < 0} after a step where it changed
// (zero_set_topology.h); step -1 is the source's own, f(., 0).
struct TopologyFrame {
  int step = -1;
  int components = 0, handles = 0, cavities = 0;
};

struct Report {
  std::vector<std::string> repairs;   // what input.h repaired on the private copies
  std::vector<std::string> warnings;  // the map's own figures say it failed somewhere: what to change
  vcg::Point3i gridNodes = vcg::Point3i(0, 0, 0);
  double cellSize = 0;
  int steps = 0;
  double alpha = 0;
  int anchors = 0;
  std::string morphMode;    // Morph::Describe()
  std::string placement;    // how the target was placed in the source's frame
  std::string morphsTried;  // where a first map failed and other morphs were tried: each map's figures
  std::string placementsTried;  // where the map at centre-and-scale failed and the overlap placement was tried
  std::string solver;       // the velocity solver (VelocitySolver::Method)
  int threads = 1;
  int sourceVertices = 0;
  SolverFigures solverFigures;
  StageTimes times;
  MapQuality quality;
  // The cut a continuous map needs (topology.h, NeededCut), when the source mesh's topology is
  // that of f0's inside set (cutPredicted).
  bool cutPredicted = false;
  std::string cutNotChecked;  // why not, when it is not
  int neededComponents = 0, neededBoundaryLoops = 0, neededEulerCharacteristic = 0;
  std::vector<TopologyFrame> topologyAlongMorph;  // f(., 0), then each frame where it changed
  std::vector<TopologyEvent> topologyEvents;     // every event, exact from f (zero_set_topology.h)
  std::vector<EventSurgery> surgery;            // one per topology event, in the same order
  int untangledVertices = 0;  // vertices moved by untangle.h (summed over its two runs: pipeline.cpp)
  int stretchedSplit = 0;     // vertices added where the untangled map stretched edges (refine_stretched.h)
  int seamSplit = 0;          // vertices added where the images cross the target's texture seams (RefineAtSeams)
  int tearsOpened = 0;        // faces removed where the map tore beside a rim (refine_stretched.h)
  int rimsGlued = 0;          // disc pairs whose two rims were brought onto one curve (glue_rims.h)
  std::string texture;        // what the cut's texture coordinates are (transfer.h); empty: not asked
  bool texCoordsPulled = false;
  int cutVertices = 0, cutFaces = 0;
  int pointsAdded = 0;        // vertices surgery added where rims opened (surgery.h, step 4)
  int cutBoundaryLoops = 0;
  int cutEulerCharacteristic = 0;
  int cutComponents = 0;
  long peakMemoryKiB = 0;   // peak resident set size of the process, if known

  int HolesCut() const;  // events with outcome Cut
  bool CutAsNeeded() const {
    return cutComponents == neededComponents && cutBoundaryLoops == neededBoundaryLoops &&
           cutEulerCharacteristic == neededEulerCharacteristic;
  }
  // Multi-line text for the log, the tests and the benchmark.
  std::string ToText() const;
};

// One number of a Report, by name.
enum class FigureUnit {
  Count,    // an integer
  Share,    // in [0, 1]; the log and the benchmark print it as a percentage
  Seconds,
  Cells,    // grid cells
  Number,   // anything else
};
enum class FigureLine {
  None,     // returned (pymeshlab) but not on a line of its own: the log says it in words
  Times,    // "times (s): SDF 0.290, ..."
  Quality,  // "map quality: on-surface 99.79%, ..."
};
struct Figure {
  const char *name;   // snake_case: pymeshlab's key, the benchmark's column
  FigureUnit unit;
  FigureLine line;
  const char *label;  // on its line of the log ("on-surface"); the benchmark's header
  bool benchmark;     // a column of the benchmark's row
  double (*value)(const Report &);
  // "99.79%", "2.00 cells", "0.290": as the log and the benchmark print it.
  std::string Text(const Report &report) const;
};

// Every figure, in the order of the benchmark's row and of each log line.
const std::vector<Figure> &FigureTable();

} // namespace eulermap
