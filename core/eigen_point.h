// eulermap::ToEigen, ToPoint — a Point3 as Eigen's 3-vector and back, for the places that
// hand points to Eigen's solvers and decompositions (placement, morph, saddles, cut axes).
#pragma once

#include "mesh.h"

#include <Eigen/Core>

namespace eulermap {

inline Eigen::Vector3d ToEigen(const Point3 &p) { return Eigen::Vector3d(p.X(), p.Y(), p.Z()); }
inline Point3 ToPoint(const Eigen::Vector3d &v) { return Point3(v.x(), v.y(), v.z()); }

} // namespace eulermap
