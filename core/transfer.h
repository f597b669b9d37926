// Texture coordinates pulled from the target (the inverse method, paper Sec. 4.1).
//
// Each vertex of the cut source knows the target face under its image and the
// barycentric coordinates there (ClosestHit); a face of the cut source takes the
// target's coordinates at its three corners, interpolated in the target face.
#pragma once

#include "closest.h"

#include <vector>

namespace eulermap {

enum class TexCoordKind { None, PerWedge, PerVertex };

// Which texture coordinates m carries: per wedge when some wedge coordinate differs
// from (0,0), else per vertex when some vertex coordinate does, else none.
TexCoordKind DetectTexCoords(const Mesh &m);

// in:  cut, whose vertex v maps to hits[v] on `target` (a face of `target` itself, or of
//      a copy with the same face order: hits index faces by position)
// out: wedge texture coordinates of every face of `cut`, texture index n of the target
//      face; cut.textures = target.textures. Returns false (and leaves `cut` as it is)
//      when the target has no texture coordinates.
bool PullTexCoords(Mesh &cut, const Mesh &target, const std::vector<ClosestHit> &hits, const Mesh &hitMesh);

} // namespace eulermap
