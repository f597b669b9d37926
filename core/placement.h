// eulermap::Similarity and the placement of the target in the source's frame.
//
// The morph runs between the source M0 and the placed target P(M1); images found on
// P(M1) are mapped back onto the real target by P^-1 (DESIGN.md: align option).
//   - align = none, no anchors:           P = identity
//   - align = centre-and-scale, no anchors: P moves the target's centroid onto the
//     source's and scales its bounding-box diagonal to the source's
//   - align = overlap, no anchors: centre-and-scale here; the pipeline then moves and
//     scales the target to overlap the source's inside most (overlap.h)
//   - 1 to 3 anchors, or more:           P = the least-squares similarity taking the
//     target anchors b_i onto the source anchors a_i (1 anchor: translation only;
//     2 anchors: translation and scale; 3 or more: Umeyama's rotation too)
#pragma once

#include "mesh.h"

#include <Eigen/Core>
#include <string>
#include <vector>

namespace eulermap {

struct Similarity {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  double scale = 1;
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();

  Point3 Apply(const Point3 &p) const;  // scale * rotation * p + translation
  Similarity Inverse() const;
};

enum class Align { None, CentreAndScale, Overlap };  // Overlap: overlap.h, from centre-and-scale

// Centroid of the surface (area-weighted).
Point3 SurfaceCentroid(const Mesh &mesh);

// The placement P described above. `from` are target-side anchor points (b_i),
// `to` the source-side ones (a_i); with no anchors `align` decides.
Similarity FitPlacement(const Mesh &source, const Mesh &target, const std::vector<Point3> &from,
                        const std::vector<Point3> &to, Align align);

// Whether the anchors mirror each other (left and right swapped): the best similarity
// taking `from` (b_i) onto `to` (a_i), and the best one taking the mirror image of `from`
// (x negated) onto `to`, both by Umeyama's least squares, as RMS residuals. Only 4 or more
// anchors that span space can tell (3 points always fit their mirror image by a rotation):
// otherwise both are 0.
struct MirrorTest {
  double residual = 0, mirroredResidual = 0;
  bool Mirrored() const { return mirroredResidual < 0.5 * residual; }
};
MirrorTest TestMirror(const std::vector<Point3> &from, const std::vector<Point3> &to);

// Applies s to every vertex of m (positions and normals).
void Transform(Mesh &m, const Similarity &s);

// The 23 turns of the cube other than the identity (the proper rotations that permute the
// axes and flip their signs): 6 of 90 degrees about the axes, 8 of 120 degrees about the
// cube's diagonals, 3 of 180 degrees about the axes and 6 about its faces' diagonals, the
// smallest angle first.
std::vector<Eigen::Matrix3d> QuarterTurns();

// The 6 orders of the axes, each as the smallest proper rotation that lays them so (the
// identity first, then 90 degrees about each axis and 120 about the cube's diagonal either
// way): a hole's axis along x, y or z laid on any of them.
std::vector<Eigen::Matrix3d> AxisPermutations();

// The principal axes of the mesh's surface: the eigenvectors of its area-weighted second
// moment about its centroid, as columns, the smallest moment first, a proper rotation.
Eigen::Matrix3d PrincipalAxes(const Mesh &mesh);

// The turns of the target tried where it does not map as it is (pipeline.cpp, BestPlacement):
// QuarterTurns, then, for meshes turned by other angles, the 24 rotations taking the
// target's principal axes onto the source's (each axis onto any, either way: the axes'
// order and signs say little about which parts match), the smallest angle first, less the
// identity and those already listed (for meshes whose axes are the coordinate axes, all).
std::vector<Eigen::Matrix3d> CandidateTurns(const Mesh &source, const Mesh &target);

// The centre-and-scale placement with the target turned by `turn` about its centroid first:
// its centroid onto the source's, and the diagonal of its bounding box scaled to the
// source's; for a turn, the boxes along each mesh's own principal axes (PrincipalAxes),
// since an axis-aligned box's diagonal changes as the mesh turns, so that a turned pair is
// placed as the same pair upright.
Similarity CentreAndScale(const Mesh &source, const Mesh &target, const Eigen::Matrix3d &turn = Eigen::Matrix3d::Identity());

// "turned 90 degrees about the x axis", "turned 120 degrees about (1, -1, 1)", "turned 47
// degrees about (0.41, -0.20, 0.89)".
std::string DescribeTurn(const Eigen::Matrix3d &r);

} // namespace eulermap
