// eulermap::CutShape, eulermap::ShapeOf, eulermap::CutAxis — how the tracked surface is cut
// at a topology event of {f(., t) < 0} (zero_set_topology.h), and in which direction
// (surgery.h uses both).
//
// Shape, from the event's kind alone:
//   Discs  (HandleGained, PartsMerged): two sheets of the surface meet at the event; each
//          loses a disc (paper Sec. 3.4, Fig. 5: sphere -> torus);
//   Band   (HandleLost, PartSplit): a neck of the surface pinches at the event; a band
//          around it goes (torus -> sphere, a dumbbell splitting);
//   None   (parts and cavities born or dying, cavities opening): no sheet of the tracked
//          surface meets another or parts there.
//
// Axis: Discs: the direction in which the two sheets face each other; Band: the direction
// the neck runs (the normal of the plane that cuts it). At a non-degenerate critical point
// x of f(., t) (where the event happens, Morse theory) both are the principal direction of
// f's Hessian whose curvature has the sign the other two do not have: two blobs merging
// (f has a maximum along the gap, minima across), a membrane tearing (a minimum through
// it, maxima in its plane), a neck pinching (a maximum along it, minima across), a hole
// closing (a minimum through it, maxima across). The Hessian is read by central differences
// one cell wide around the event's node. The saddle of V_k of the matching kind nearest to
// x (saddle.h: kind 2 for Discs, 1 for Band), if one lies within kSaddleCells, gives this
// direction instead (its stable line / the normal of its stable plane), as the paper's
// surgery does; it never decides whether a cut happens.
#pragma once

#include "field.h"
#include "saddle.h"
#include "zero_set_topology.h"

#include <array>
#include <vector>

namespace eulermap {

enum class CutShape { None, Discs, Band };

// in: an event's kind; out: the cut it calls for (above)
CutShape ShapeOf(TopologyEventKind kind);

struct CutDirection {
  Point3 axis;             // unit length
  bool fromSaddle = false; // a saddle of V gave it (else f's Hessian)
};

constexpr double kSaddleCells = 2;  // a saddle of V this near the event orients its cut

// in:  the event (its shape not None), f(., t_k+1) on the grid, the saddles of V_k
// out: the cut's axis (above)
CutDirection CutAxis(const TopologyEvent &event, const ScalarField &f, const std::vector<Saddle> &saddles);

// The normals of the planes a band may take where the axis' own is no band of the event's
// (surgery.h, step 2), in order: the principal directions of f's Hessian at the event's node
// (by increasing curvature), then the grid's 13 directions (to a face, an edge and a corner
// of the cell), unit length. The Hessian, read one cell wide, is the shape of f at a point:
// where a window fills between thin parts (the three windows under stool3's seat, between
// two legs and a ring, grown over by a sphere) none of its planes meets the window's rim in
// one loop, and one of the grid's crosses the window.
std::vector<Point3> BandPlanes(const TopologyEvent &event, const ScalarField &f);

} // namespace eulermap
