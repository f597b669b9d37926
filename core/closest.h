// eulermap::ClosestPoint — nearest point on a triangle mesh: a bounding-volume tree over
// the faces, with vcglib's point–triangle distance (face::PointDistanceBase) at the
// leaves. Not vcglib's GridStaticPtr / tri::GetClosestFaceBase: those mark faces in the
// mesh (not thread-safe) and cost O((distance/voxel)^4) far from the surface (closest.cpp
// has the figures). Used for the images' projection onto the target, the quality
// measures and untangling; the grid's distances come from distance_transform.h.
#pragma once

#include "mesh.h"

#include <functional>
#include <memory>

namespace eulermap {

struct ClosestHit {
  const Face *face = nullptr;  // nullptr when nothing lies within maxDist
  Point3 point;                // nearest point on the surface
  Point3 barycentric;          // of `point` in `face`
  double distance = 0;
};

// Barycentric coordinates of the projection of p onto the plane of triangle (a, b, c):
// (l0, l1, l2) with l0 + l1 + l2 = 1 and l0 a + l1 b + l2 c that projection; outside
// [0, 1] where it falls outside the triangle. A degenerate (zero-area) triangle gives
// the weights of its corner nearest to p.
Point3 Barycentric(const Point3 &a, const Point3 &b, const Point3 &c, const Point3 &p);

class ClosestPoint {
 public:
  // Indexes `mesh`'s faces (updates its bounding box and face normals). The mesh must
  // outlive this object and keep its faces where they are.
  explicit ClosestPoint(Mesh &mesh);
  // Nearest surface point to p within maxDist (default: no limit). Thread-safe.
  ClosestHit Query(const Point3 &p, double maxDist = -1) const;
  // Nearest surface point to p on the faces that `among` accepts. Thread-safe when
  // `among` is.
  ClosestHit Query(const Point3 &p, const std::function<bool(const Face &)> &among) const;

 private:
  struct Tree;
  Mesh &mesh_;
  std::shared_ptr<const Tree> tree_;
};

} // namespace eulermap
