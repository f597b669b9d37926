// Untangling of the mapped surface (ours, not the paper's).
//
// Where the source has features thinner than a grid cell (ears, horns), both sides of
// the feature share one trilinear velocity and land on top of each other, so some
// mapped faces face against the target. Untangle relaxes those places only: the
// vertices of such faces and their `rings`-ring move to the mean of their neighbours'
// images and back onto the target (closest point), round after round, until no face is
// flipped or `rounds` are spent.
//   in/out: mapped (positions on the target; face normals updated)
//   returns the number of vertices moved at least once
#pragma once

#include "closest.h"

#include <vector>

namespace eulermap {

int Untangle(Mesh &mapped, const ClosestPoint &target, int rounds = 50, int rings = 0);

} // namespace eulermap
