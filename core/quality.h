// Measures of the map F: M0 -> M1 that the report, the tests and the benchmark share
// (definitions in report.h, MapQuality).
#pragma once

#include "closest.h"
#include "report.h"

#include <vector>

namespace eulermap {

// Share of points within `tolerance` of the surface indexed by `surface`.
double OnSurfaceRate(const std::vector<Point3> &points, const ClosestPoint &surface, double tolerance);

// Share of `samples` uniform random points on `target` (fixed seed) lying within
// `tolerance` of the surface `mapped`. `uncovered`, if given, receives the samples that
// are not, grouped into parts (samples closer than `tolerance` to one another belong to
// one part), largest first: where on the target the map is missing (a part of the target
// that the morph grows away from the moving surface, or one thinner than a grid cell).
double Coverage(Mesh &target, Mesh &mapped, double tolerance, std::vector<UncoveredPart> *uncovered = nullptr,
                int samples = 20000);

// Area share of the faces of `mapped` whose normal points against the normal of the
// target face nearest to their centroid.
double FlippedAreaShare(Mesh &mapped, const ClosestPoint &target);

// Longest edge of m, and the mean length of its faces' edges (an edge between two faces counted twice).
double LongestEdge(const Mesh &m);
double MeanEdgeLength(const Mesh &m);

// The longest edge of `mapped` that the map stretches: mapped more than kStretchFactor times
// its length on `cut` (the same faces on the source) over `scale` (the placement's, source
// units per target unit). An edge as long on the source is the source's own coarseness,
// not the map's (a 1280-face ellipsoid onto itself at 1.2 times: edges over its bump of 7.5%
// of the diagonal). Its midpoint on `mapped` into `midpoint`; 0 if there is none.
constexpr double kStretchFactor = 2;
double LongestStretchedEdge(const Mesh &cut, const Mesh &mapped, double scale, Point3 *midpoint);

// Per-vertex area distortion |log2(A_mapped / A_source)|, A the area of the faces around
// the vertex and the ratio normalised by the total areas, written to the vertices'
// quality of `cut` (which shares faces and vertex order with `mapped`); returns the mean.
double StoreDistortion(Mesh &cut, const Mesh &mapped);

} // namespace eulermap
