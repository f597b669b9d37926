// eulermap::Surgery — the cut of the source where the moving surface changes topology
// (paper Sec. 3.4; DESIGN.md: saddle.h, surgery.h), done step by step along the
// tracking pass, and eulermap::FillHoles.
//
// The tracked surface is the source's triangles over the tracked points (the source's
// vertices, whose trajectories the pipeline's Tracker follows, and the points this class
// adds to that Tracker). After each step k, for each event of step k that the plan leaves
// to surgery (surgery_plan.h: events exact from f, at a node x, zero_set_topology.h):
//   1. which: the event's kind gives the cut's shape (cut_axis.h): two sheets meeting
//      (handle gained, parts merged) lose a disc each, a pinching neck (handle lost, part
//      split) a band; births and cavities are not cut. The tracked surface takes part only
//      if some tracked triangle lies within kTakesPartCells + the hole radius of x (a part
//      grown from nothing, which no tracked point reaches, changes topology far from every
//      tracked triangle). The tracked sheets lag the level set near a critical point, where
//      V vanishes (5 to 6 cells at sphere -> 3holes, 3 at a blob splitting, at grid 48-64;
//      a torus's hole opening as the grown sphere withdraws, sphere -> ring2 at 128 cells:
//      13.7 cells at the event's step, within reach 4 steps later): an event the tracked
//      surface is farther from waits for it, and is acted on at the first step it arrives,
//      as long as it comes nearer at every step; else it is reported, not cut (an untracked
//      part's event). Where sheets meet, both must be tracked
//      (step 2 b finds a tracked face on each side): a part grown from nothing that merges
//      with the surface is reported, not cut. Where a part dies, the piece of the tracked
//      surface that shrank with it (already cut off by the events before, and all within
//      kCollapsedCells + the hole radius of the node) maps onto nothing: it goes (genus 2 ->
//      sphere in the linear blend: the outer arcs of both loops pinch off and vanish).
//   2. cut, oriented by the axis d of cut_axis.h (a saddle of V_k near x, else f's Hessian):
//      (a) the paper's rule: the faces within the hole radius of x, and all faces around a
//          point inside that sphere (no rim vertex is left where trajectories part);
//      (b) the faces nearest to x that the event's own geometry crosses. Near a critical
//          point V vanishes, so the tracked sheets part before they reach x and may never
//          meet the sphere. Discs: on each side, the nearest face the line (x, d) pierces, else
//          (a sheet meeting it at a tip) the nearest within 60 degrees of d (within
//          kReachCells + hole radius), with the faces within the radius of that point
//          joined to it through faces within the radius (one disc of that sheet, not of
//          another layer of the tracked surface that passes by);
//          Band: the loop of faces crossing the plane through x normal to d around the neck,
//          all of it, however far it reaches (a band cut short is a strip: one loop, not two);
//          a band parts the surface where a part splits and never where a handle is lost:
//          where d's band (with (a) and (c)) does otherwise, the band of fewest faces along
//          a principal direction of f's Hessian that does what the event does;
//      (c) at the event's own step, where the step closes a gap at x: the cut grows over the
//          faces joined to it whose corners lie in cells the step swept into the inside set
//          between two fronts around x (the nodes with f(., t_k) >= 0 > f(., t_k+1) joined to
//          x). Where flat fronts meet across a whole section (a chair's rail growing from both
//          legs, chair -> chair_rails) the sheets meet over that section at once, and a disc
//          of the hole radius leaves the rest of each front as a membrane the pull-back folds
//          onto the walls, its faces spanning the section (mapped edges of 6.4% of the
//          target's diagonal at 96 cells). Where a hole's walls meet (a handle lost as a bore
//          fills, rocker-arm -> cow inflated), the band grows over the walls facing the gap:
//          a band of the hole radius left the rest of the wall as a flattened tube along a
//          crease of the target, half of it flipped (2.52% of the map after untangling
//          against 0.70% with the wall cut). A neck that pinches sweeps nothing in at x: its
//          band is (a) and (b)'s;
//      of (a) and (c), only the faces joined to (b)'s discs or band through the cut's own
//      faces, corner to corner: another layer of the tracked surface within the radius (a
//      fold, a wall beside the meeting fronts) keeps its faces. A piece of it cut opened a
//      hole no event called for: ring1 -> ring2 at 64 cells grown at centre-and-scale, 13
//      faces of the sphere apart from both discs, 3 loops where 2 are needed; chair ->
//      chair_rails at 96 cells (with the topology-keeping growth of docs/NOTES.md), two
//      small holes beside the discs on the front legs, 10 loops where 8 are needed;
//   3. clean: the rim left must be a manifold boundary and look deliberate:
//        - ears: a face with two or more edges on a rim goes (no dangling faces);
//        - non-manifold vertices: where the faces around a vertex form two or more fans,
//          all but the largest fan go;
//        - islands: a piece cut off from the rest of its component with less than 2% of
//          that component's area (left between the sphere's passes over a sheet) goes,
//      repeated until nothing changes; so each sheet loses one disc, a pinching neck one band;
//   4. refine: once the surface has been cut, the faces with a corner on a rim have each
//      tracked edge longer than 2 cells split at its midpoint; when the morph grows the
//      surface into parts of the target (asked from the start), so has every edge stretched
//      to more than twice its length on the source, wherever it lies. A map that cuts
//      nothing and grows nothing keeps the source's own faces. Only at the rim, else: a
//      sheet stretched away from every rim after a cut is one pulled over a part that
//      another layer of the map covers (a scan's arm, held against its side, lifted off it:
//      TOPKIDS kid01 -> kid00 at 64 cells, where splitting every stretched edge and every
//      child of a rim face added 27292 points, 41.6% of the mapped area flipped as tracked;
//      625 points and 17.3% at the rim alone). A hole cut by a 1-cell sphere opens to the
//      size of the target's handle (sphere -> torus: the loop becomes the torus's inner
//      circle, 56 cells long at 48 cells), and its rim would be stretched up to 18 cells
//      between vertices; a surface growing into a part of the target (grow_shrink.h)
//      stretches a patch of a few faces over the whole part. The new
//      point lies at the edge's midpoint on the source too; its position at step k is the
//      midpoint of the edge's tracked ends pulled back onto f(., t_k+1) = 0 (the ends are
//      both on the same side of the parting by then), and from there it has its own
//      trajectory through the same fields. At most kAddedPerVertex points are added per
//      vertex of the source. Not split: an edge with an end off f(., t_k+1) = 0 (the part of
//      the surface it followed vanished without a cut) or whose chord runs outside the
//      surface (its ends on two rims of an opening): a point put there lands on an end.
// The map stays Eulerian: cutting never moves a point, and every vertex of the cut source
// is mapped by its own trajectory. The vertices that stay keep the images of the single
// tracking pass. With no event cut, the cut source is the source.
#pragma once

#include "cut_axis.h"
#include "edge_faces.h"
#include "report.h"
#include "tracker.h"

#include <array>
#include <functional>
#include <utility>
#include <vector>

namespace eulermap {

constexpr int kAddedPerVertex = 4;  // the refinement's budget
constexpr double kIslandShare = 0.02;  // a piece of the cut with less of its component's area (on the source) is an island

class Surgery {
 public:
  // in: source (no deleted vertices or faces; vertex n is point n of the pipeline's Tracker),
  //     the sphere's radius and the grid cell (world units), the morph's events and the plan
  //     for each (surgery_plan.h: those left Planned are acted on at their step)
  // growing: the morph grows the surface into parts of the target (grow_shrink.h,
  // inflate_shrink.h): stretched edges are split anywhere, from the start (step 4)
  Surgery(const Mesh &source, double radius, double cell, const std::vector<TopologyEvent> &events,
          const std::vector<EventCut> &plan, bool growing);

  // One step, once the tracked points have moved to t_k+1.
  // in:  k; the saddles of V_k (only to orient cuts; may be empty), fCur = f(., t_k) and
  //      fNext = f(., t_k+1), the tracker (the source's vertices first, in order)
  // out: faces cut at the step's planned events and at those the tracked surface reaches
  //      now (step 1), the surface cleaned and refined (steps 1-4 above); the points added
  //      appended to tracker; those events' outcomes set
  void Step(int k, const std::vector<Saddle> &saddles, const ScalarField &fCur, const ScalarField &fNext,
            Tracker &tracker);
  // Whether step k has events to act on, or waits for the tracked surface to reach one (the
  // pipeline looks for V's saddles only then).
  bool Acts(int k) const;
  // Whether edges are split (step 4): once a cut has changed the surface, or from the start
  // when the morph grows it. A map that cuts nothing and grows nothing keeps the source's faces.
  bool SplitsStretched() const { return growing_ || cut_; }

  // One per event of the morph, in order (faces removed and rim length are filled by Build).
  const std::vector<EventSurgery> &Outcomes() const { return outcomes_; }
  // The added points that faces of the cut source use (those of removed faces are not
  // counted: they are not in the cut).
  int PointsAdded() const;

  // in:  source (as given to the constructor), tracked (the tracker's final points)
  // out: cut: the source refined where points were added, without the removed faces and the
  //      vertices left without faces; compact; vertex and face data of the source (wedge
  //      texture coordinates, colours, normals, ...) interpolated onto what is new.
  //      outcomes: Outcomes() with each cut's faces removed and rim length on the source.
  //      Returns the image (final tracked position) of every vertex of cut.
  std::vector<Point3> Build(Mesh &source, const std::vector<Point3> &tracked, Mesh &cut,
                            std::vector<EventSurgery> &outcomes) const;

 private:
  struct Tri {
    std::array<int, 3> v;            // points
    int root = 0;                    // the source face it lies in
    std::array<Point3, 3> bary;      // barycentric coordinates of its corners in the root face
    std::array<bool, 3> border{};    // edge e (v[e], v[e+1]) lies on a boundary of the source
    int state = kAlive;              // kAlive, kSplit, or the outcome (event) that removed it
    int component = 0;               // connected component of the source
  };
  static constexpr int kAlive = -1, kSplit = -2;

  std::vector<Point3> Positions(const std::vector<Point3> &tracked) const;
  EdgeFaces AliveEdges() const;  // the alive faces around each edge
  void AliveEdges(EdgeFaces &edges) const;  // the same, into edges (its room kept)
  // Distance from x to the nearest alive tracked triangle (at most `limit`, returned when none is nearer).
  double NearestTriangle(const Point3 &x, double limit, const std::vector<Point3> &position) const;
  // The connected piece of alive faces nearest to x if all of it lies within reach of x, else none.
  std::vector<int> CollapsedPiece(const Point3 &x, double reach, const std::vector<Point3> &position) const;
  // Step 2 (a): the faces within the sphere's radius of x, or with a corner inside it.
  std::vector<int> InSphere(const Point3 &x, const std::vector<Point3> &position) const;
  // Step 2 (b): the faces the event's geometry crosses nearest to x (Discs: on each side,
  // the nearest the line (x, axis) pierces, else the nearest within a cone around it, with
  // those within the radius there; Band: the loop
  // crossing the plane through x normal to axis).
  // bothSheets: set false when a side has no tracked face (Discs).
  std::vector<int> Crossing(const Point3 &x, const Point3 &axis, CutShape shape, const std::vector<Point3> &position,
                            bool *bothSheets) const;
  // The alive faces less `cut`, less the islands Clean would remove: their pieces, boundary
  // loops and Euler characteristic (what a band changes).
  struct SurfaceFigures {
    int parts = 0, loops = 0, euler = 0;
  };
  SurfaceFigures Figures(const std::vector<int> &cut) const;
  // The Euler characteristic of the faces (distinct), their edges and corners: 1 for a disc,
  // 0 for a band round a neck or a handle.
  int Euler(const std::vector<int> &faces) const;
  // Step 2 (c): the alive faces joined to seeds (not among them) through faces whose corners
  // are all near.
  std::vector<int> Spread(const std::vector<int> &seeds, const std::function<bool(const Point3 &)> &near,
                          const std::vector<Point3> &position) const;
  // The faces of `faces` joined to the seeds (among them) through corners of faces it holds.
  std::vector<int> JoinedTo(const std::vector<int> &seeds, const std::vector<int> &faces) const;
  // The faces joined to seed through edges that `faces` holds (seed among them).
  std::vector<int> ConnectedFrom(int seed, const EdgeFaces &faces) const;
  // cutting: the outcomes (events) that cut at this step, with their positions
  void Clean(const std::vector<Point3> &position, const std::vector<std::pair<int, Point3>> &cutting);
  // position: every point's tracked position, extended with the points added
  void Refine(std::vector<Point3> &position, const ScalarField &fNext, Tracker &tracker);

  double radius_, cell_;
  int sourceVertices_ = 0, sourceFaces_ = 0;
  std::vector<EventSurgery> outcomes_;          // per event seen
  std::vector<Tri> tris_;
  std::vector<double> componentArea_;           // per component of the source, its area
  std::vector<Point3> sourcePosition_;          // per point: where it lies on the source
  std::vector<std::array<int, 2>> parents_;     // per added point: the edge it splits
  std::vector<std::size_t> trackedAs_;          // per point: its index in the pipeline's Tracker
  std::vector<TopologyEvent> events_;           // the morph's, in order
  std::size_t next_ = 0;                        // the first event of a step not yet seen
  std::vector<std::size_t> arriving_;           // events away from the tracked surface, which is nearing them
  bool growing_ = false;                        // the morph grows the surface: stretched edges split anywhere
  bool cut_ = false;                            // a cut has changed the surface: long edges at its rims split
};

// in:  cut (after surgery)
// out: filled: a copy of cut with every boundary loop closed by vcglib's ear cutting
//      (tri::Hole, minimum-weight ears). Returns the number of loops filled.
int FillHoles(Mesh &cut, Mesh &filled);

} // namespace eulermap
