// eulermap::ClosestPoint — nearest point on a triangle mesh, through vcglib's
// GridStaticPtr and tri::GetClosestFaceBase (DESIGN.md: use what vcglib has).
#pragma once

#include "mesh.h"

#include <vcg/space/index/grid_static_ptr.h>

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
  Mesh &mesh_;
  vcg::GridStaticPtr<Face, double> index_;
};

} // namespace eulermap
