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
//   stool, bench, frame, mug, ladder, dumbbell (see shapes.cpp)
//   plate2, plate3          a flat oval slab with 2 or 3 round holes             genus 2, 3
//   thin_ring               a torus with a thin tube (ring 0.6, tube 0.1)        genus 1
//   box_tunnel              a cube pierced by a square tunnel                    genus 1
//   two_balls, snowman      a large and a small ball, apart / overlapping        2 parts / genus 0
//   armchair                chair with arm rests on posts                        genus 2
//   pretzel, spectacles, key, hand, star, cage, cup, round_table: made in session 32
//   wheel                   a rim, a hub and five spokes                         genus 5
//   trefoil, spring         a tube round a trefoil knot / three turns of a helix genus 1 / 0
//   link                    two rings interlocked, apart                         2 parts, genus 2
//   bowl, vase              half a shell open upwards / a hollow ball with a
//                           narrow neck (hollow targets)                         genus 0
//   bookcase                a box with two pockets open at the front             genus 0
//   teapot, hare            a body with a handle, a spout and a knob / a body,
//                           a head and two thin ears                             genus 1 / 0
//   NAME_turned             any of them turned a quarter about the x axis (as a file made
//                           with another axis up comes); NAME_tilted: 40 degrees about x,
//                           then 25 about y
#pragma once

#include "core/mesh.h"
#include "core/pipeline.h"

#include <Eigen/Core>
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

// The turn a name's suffix gives its shape (about the origin, which each shape is made
// around): _turned, _tilted as above, the identity for none; and the name less its suffix.
Eigen::Matrix3d ShapeTurn(const std::string &name, std::string *base = nullptr);

// A map between two shapes, in the figures the family tests assert and print.
struct FamilyFigures {
  int eventsCut = 0, discPairs = 0, bands = 0;  // surgery's cuts: each disc pair or band adds 2 loops
  double longestShare = 0;  // longest mapped edge / the target's diagonal
  std::string line;  // `family | SOURCE -> TARGET | CELLS | ...`: one row of the closing note's table
};

// in:  the pair's names, the grid's cells, the target mesh, the map's result, its wall time
// out: its figures
FamilyFigures Figures(const std::string &source, const std::string &target, int cells, const Mesh &targetMesh,
                      const Result &result, double seconds);

} // namespace eulermap::testing
