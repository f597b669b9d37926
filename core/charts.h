// Texture coordinates of a mesh: which it carries, and where they are continuous (paper
// Sec. 4.1 pulls them across the map; a face must not take them from both sides of a seam).
#pragma once

#include "mesh.h"

#include <array>
#include <vector>

namespace eulermap {

enum class TexCoordKind { None, PerWedge, PerVertex };

// Which texture coordinates m carries: per wedge when some wedge coordinate differs
// from (0,0), else per vertex when some vertex coordinate does, else none.
TexCoordKind DetectTexCoords(const Mesh &m);

// The coordinate at corner c of face f, of the given kind (PerWedge: the wedge's,
// PerVertex: the vertex's).
vcg::TexCoord2d CornerTexCoord(const Face &f, int c, TexCoordKind kind);

// Seams: where the texture coordinates jump. The faces across the three edges of every
// face (edge e runs from corner e to e + 1) where the coordinates continue: the face
// shares the edge's two vertices and, at both, its coordinates and texture index are
// equal (exactly: a mesh stores a shared coordinate once per vertex, or copies it
// unchanged into each wedge); -1 at a seam or a border. A chart is a piece of surface
// crossed without passing a seam; it may meet itself across one (a torus with u and v
// wrapping from 1 to 0 is one chart with two seams).
struct TexCoordSeams {
  std::vector<std::array<int, 3>> across;  // per face (index in m.face)
};
TexCoordSeams FindSeams(const Mesh &m, TexCoordKind kind);

// in:  the seams of a mesh (FindSeams)
// out: per face, its chart: the same number for the faces joined across edges where the
//      coordinates continue, another for each other chart
std::vector<int> Charts(const TexCoordSeams &seams);

} // namespace eulermap
