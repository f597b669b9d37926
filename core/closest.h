// eulermap::ClosestPoint — nearest point on a triangle mesh: a bounding-volume tree over
// the faces, with vcglib's point–triangle distance (face::PointDistanceBase) at the
// leaves. Not vcglib's GridStaticPtr / tri::GetClosestFaceBase: those mark faces in the
// mesh (not thread-safe) and cost O((distance/voxel)^4) far from the surface (closest.cpp
// has the figures). Used for the images' projection onto the target, the quality
// measures and untangling; the grid's distances come from distance_transform.h.
#pragma once

#include "mesh.h"

#include <memory>

namespace eulermap {

struct ClosestHit {
  const Face *face = nullptr;  // nullptr when nothing lies within maxDist
  Point3 point;                // nearest point on the surface
  Point3 barycentric;          // of `point` in `face`
  double distance = 0;
};

class ClosestPoint {
 public:
  // Indexes `mesh`'s faces (updates its bounding box and face normals). The mesh must
  // outlive this object and keep its faces where they are.
  explicit ClosestPoint(Mesh &mesh);
  // Nearest surface point to p within maxDist (default: no limit). Thread-safe.
  ClosestHit Query(const Point3 &p, double maxDist = -1) const;

 private:
  struct Tree;
  Mesh &mesh_;
  std::shared_ptr<const Tree> tree_;
};

} // namespace eulermap
