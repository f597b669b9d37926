// eulermap::Surgery — the cut of the source where the moving surface changes topology
// (paper Sec. 3.4; DESIGN.md: saddle.h, surgery.h), done step by step along the
// tracking pass, and eulermap::FillHoles.
//
// The tracked surface is the source's triangles over the tracked points (the source's
// vertices, whose trajectories the pipeline's Tracker follows, plus points this class
// adds). After each step k:
//   1. saddles: the saddle-type zeros of V_k (saddle.h), followed over the steps as events.
//      Only a saddle where f(., t_k+1) is critical can cut: |grad f| there (central
//      differences one cell wide) below half its median on the tracked surface. Morse
//      theory: the level set changes topology only at critical points of f. V also has
//      saddles where none is (a zero of V drifting through a regularly moving surface:
//      sphere -> ellipsoid has two, with |grad f| 0.99 of the surface's), and the paper's
//      rule alone would cut there.
//   2. cut, at every step it applies:
//      (a) the paper's rule: an event whose sphere (radius = hole radius) meets the
//          tracked surface (some tracked triangle within the radius: vertex, edge or
//          interior) cuts those faces, and all faces around a point inside the sphere;
//      (b) at the step the level set passes the saddle (f changes sign there): the faces
//          nearest to it that its stable manifold crosses. Near a critical point V
//          vanishes, so the tracked sheets part before they reach the saddle and often
//          never meet the sphere (sphere -> 3holes: 5 to 6 cells away when f = 0 at the
//          saddle). Kind 2: the faces the stable line pierces on either side (within 10
//          cells + hole radius), with those within the radius of that point; kind 1: the
//          loop of faces crossing the stable plane around the neck;
//   3. clean: the rim left must be a manifold boundary and look deliberate:
//        - ears: a face with two or more edges on a rim goes (no dangling faces);
//        - non-manifold vertices: where the faces around a vertex form two or more fans,
//          all but the largest fan go;
//        - islands: a piece cut off from the rest of its component with less than 2% of
//          that component's area (left between the sphere's passes over a sheet) goes,
//      repeated until nothing changes; so each sheet loses one disc, a pinching neck one band;
//   4. refine: the faces on a rim, and from them any neighbour stretched more than twice
//      its length on the source, have each tracked edge longer than 2 cells split at its
//      midpoint. A hole cut by a 1-cell sphere opens to the size of the target's handle
//      (sphere -> torus: the loop becomes the torus's inner circle, 56 cells long at 48
//      cells), and its rim would be stretched up to 18 cells between vertices. The new
//      point lies at the edge's midpoint on the source too; its position at step k is the
//      midpoint of the edge's tracked ends pulled back onto f(., t_k+1) = 0 (the ends are
//      both on the same side of the parting by then), and from there it has its own
//      trajectory through the same fields. At most as many points are added as the source
//      has vertices.
// The map stays Eulerian: cutting never moves a point, and every vertex of the cut source
// is mapped by its own trajectory. The vertices that stay keep the images of the single
// tracking pass. With no saddle cutting, the cut source is the source.
#pragma once

#include "report.h"
#include "saddle.h"
#include "tracker.h"

#include <array>
#include <utility>
#include <vector>

namespace eulermap {

class Surgery {
 public:
  // in: source (no deleted vertices or faces; vertex n is tracked point n), the sphere's
  //     radius and the grid cell (world units)
  Surgery(const Mesh &source, double radius, double cell);

  // One step, once the pipeline's tracker has moved the source's vertices to t_k+1.
  // in:  k, V_k, fNext = f(., t_k+1), dt, tracked (the source's vertices first, in order)
  // out: events followed, faces cut, the surface cleaned and refined (steps 1-4 above)
  void Step(int k, const VectorField &V, const ScalarField &fNext, double dt, const std::vector<Point3> &tracked);

  // After the last step: the added points' last pull-back (Tracker::Settle).
  void Settle(const HermiteField &f1);

  // Every saddle event: step and position where it first cut (where it was first seen if
  // it never cut), kind, whether it cut.
  const std::vector<SaddleEvent> &Saddles() const { return saddles_.Events(); }
  // The added points that faces of the cut source use (those of removed faces are not
  // counted: they are not in the cut).
  int PointsAdded() const;

  // in:  source (as given to the constructor), tracked (the source vertices' final positions)
  // out: cut: the source refined where points were added, without the removed faces and the
  //      vertices left without faces; compact; vertex and face data of the source (wedge
  //      texture coordinates, colours, normals, ...) interpolated onto what is new. holes:
  //      one entry per cutting event (faces of the tracked surface removed, rim length on
  //      the source). Returns the image (final tracked position) of every vertex of cut.
  std::vector<Point3> Build(Mesh &source, const std::vector<Point3> &tracked, Mesh &cut,
                            std::vector<HoleEvent> &holes) const;

 private:
  struct Tri {
    std::array<int, 3> v;            // points
    int root = 0;                    // the source face it lies in
    std::array<Point3, 3> bary;      // barycentric coordinates of its corners in the root face
    std::array<bool, 3> border{};    // edge e (v[e], v[e+1]) lies on a boundary of the source
    int state = kAlive;              // kAlive, kSplit, or the event that removed it
    bool refinable = false;
    int component = 0;               // connected component of the source
  };
  static constexpr int kAlive = -1, kSplit = -2;

  std::vector<Point3> Positions(const std::vector<Point3> &tracked) const;
  // Faces nearest to the saddle that its stable manifold crosses (kind 2: pierced by the
  // stable line on each side, with those within the sphere's radius there; kind 1: the loop
  // crossing the stable plane).
  std::vector<int> StableCrossing(const Saddle &saddle, const std::vector<Point3> &position) const;
  // cutting: the events that cut at this step, with their saddles' positions
  void Clean(const std::vector<Point3> &position, const std::vector<std::pair<int, Point3>> &cutting);
  // position: every point's tracked position, extended with the points added
  void Refine(std::vector<Point3> &position, const ScalarField &fNext);

  double radius_, cell_;
  int sourceVertices_ = 0, sourceFaces_ = 0;
  SaddleTracker saddles_;
  std::vector<Tri> tris_;
  std::vector<double> componentArea_;           // per component of the source, its area
  std::vector<Point3> sourcePosition_;          // per point: where it lies on the source
  std::vector<std::array<int, 2>> parents_;     // per added point: the edge it splits
  std::vector<std::array<int, 2>> trackedBy_;   // per added point: (batch, index in batch)
  std::vector<Tracker> batches_;                // trajectories of the added points
  std::vector<double> lastLevel_;               // per event: f at its saddle when last seen
};

// in:  cut (after surgery)
// out: filled: a copy of cut with every boundary loop closed by vcglib's ear cutting
//      (tri::Hole, minimum-weight ears). Returns the number of loops filled.
int FillHoles(Mesh &cut, Mesh &filled);

} // namespace eulermap
