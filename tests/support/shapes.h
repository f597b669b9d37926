// Families of shapes for topology change, made as implicit surfaces (meshes.h,
// MakeImplicit), closed and outward-oriented, about 2 units across. Each is named by what
// it is and its topology, so a test or the benchmark can ask for any of them by name.
//   sphere                  a ball, radius 0.7                                   genus 0
//   ring1 .. ring4          1 to 4 tori (ring 0.5, tube 0.18) in a row along x,
//                           each overlapping the next                            genus 1..4
//   spheres2, spheres3      2 or 3 balls of radius 0.5 in a row, 0.3 apart       2 or 3 parts
//   blob2, blob3            an ellipsoid as long as spheres2 / spheres3          genus 0
//   chair                   seat, 4 legs, a solid back (boxes 0.08 to 0.8)       genus 0
//   chair_rails             chair with stretcher rails between the legs          genus 4
//   chair_slats             chair whose back is a frame with 2 slats             genus 3
//   table                   a top on 4 legs                                      genus 0
#pragma once

#include "core/mesh.h"

#include <string>
#include <vector>

namespace eulermap::testing {

struct Shape {
  std::string name;
  int components = 1;
  int genus = 0;
};

const std::vector<Shape> &Shapes();

// in:  a name of Shapes(), the marching cubes' cells along the longest side
// out: m (throws std::invalid_argument for an unknown name)
void MakeShape(const std::string &name, Mesh &m, int cells = 128);

} // namespace eulermap::testing
