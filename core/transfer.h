// What the target carries, pulled back onto the cut source through the map (the inverse
// method, paper Sec. 4.1): each vertex of the cut source has an image on the target, and
// reads the target's texture coordinates, colour or quality there by barycentric
// interpolation in the target face under the image.
#pragma once

#include "charts.h"
#include "closest.h"

#include <vector>

namespace eulermap {

// What PullTexCoords did.
struct TexCoordPull {
  TexCoordKind from = TexCoordKind::None;  // the target's coordinates (None: nothing pulled)
  int facesAcrossSeams = 0;  // faces of the cut whose images lie on both sides of a seam
  double areaAcrossSeams = 0;  // their share of the images' area (the chords' triangles)
};

// in:  cut; target, the kind of its coordinates (DetectTexCoords) and its seams (FindSeams
//      of that kind); hits[v], the image of cut's vertex v on `target` (a query of a
//      ClosestPoint over `target`)
// out: per-wedge texture coordinates and texture index on every face of `cut`,
//      cut.textures = target.textures; nothing changed when the target has no coordinates.
// One chart per face. Around the face's images, the target's faces reachable from the
// face under one image without crossing a seam (charts.h) whose boxes meet the images'
// box (grown by the longest edge of the faces under them) form its local chart; the image
// whose local chart holds the most images (equal counts: the least summed distance of the
// others to it) gives the chart. An image in the chart reads its coordinates where it
// lies; one outside (across a seam) reads them on the chart's face nearest to it, with the
// barycentric coordinates of the image on that face's plane: the chart's coordinates
// continue linearly past its border instead of jumping to the seam's other side (on a
// torus whose u wraps from 1 to 0, a face over the seam gets u = 0.98 .. 1.02, which a
// repeating texture shows right; never 0.98 .. 0.02).
TexCoordPull PullTexCoords(Mesh &cut, const Mesh &target, TexCoordKind kind, const TexCoordSeams &seams,
                           const std::vector<ClosestHit> &hits);

// in:  cut, hits as for PullTexCoords; which attributes to pull
// out: the per-vertex colour and/or quality of cut's vertices, interpolated from the
//      target's vertices at the images.
void PullVertexAttributes(Mesh &cut, const std::vector<ClosestHit> &hits, bool colour, bool quality);

} // namespace eulermap
