// Test and benchmark support: loading the shared meshes and making analytic shapes.
#pragma once

#include "core/charts.h"
#include "core/mesh.h"

#include <functional>
#include <string>

namespace eulermap::testing {

// Path of a file in ../shared/data/meshes (relative to the project's root).
std::string DataMesh(const std::string &name);
// Path of a file in samples/.
std::string SampleFile(const std::string &name);

// Loads .off, .obj or .ply into m (positions, faces, wedge/vertex texcoords when present),
// removes unreferenced vertices and updates normals and the bounding box. Throws on failure.
void LoadMesh(const std::string &path, Mesh &m);

// Analytic shapes, closed and outward-oriented, normals and box updated.
void MakeSphere(Mesh &m, const Point3 &centre, double radius, int subdivisions = 4);
void MakeEllipsoid(Mesh &m, const Point3 &centre, const Point3 &radii, int subdivisions = 4);
void MakeBox(Mesh &m, const Box3 &box, int cellsPerSide = 1);  // 8 vertices with cellsPerSide = 1
// Torus around the z axis: ring radius R, tube radius r; texture coordinates (u, v) = the
// (ring, tube) angles / 2pi, in [0, 1], seams where an angle is 0. PerWedge: closed (the
// seams only in the wedges' coordinates: a face over a seam has u = 1 or v = 1 where its
// neighbour has 0); PerVertex: each seam's vertices doubled (u = 0 and u = 1 copies), so
// the mesh is open along the two seam circles; None: no coordinates.
void MakeTorus(Mesh &m, const Point3 &centre, double R, double r, int ringDiv = 64, int tubeDiv = 32,
               TexCoordKind texCoords = TexCoordKind::PerWedge);

// Every edge split at its midpoint, `times` times (4^times as many faces); compacted.
void RefineMidpoint(Mesh &m, int times);

// A smooth non-rigid deformation of the point p of a mesh with box `box`: stretch, bend and
// turn, scaled by `strength` (0: the identity). The benchmark's targets.
Point3 Bend(const Point3 &p, const Box3 &box, double strength);

// The zero set of f (negative inside) over box, by vcglib's marching cubes on `cells` cells
// along the box's longest side; outward-oriented. f must be positive on the box's border.
void MakeImplicit(Mesh &m, const std::function<double(const Point3 &)> &f, const Box3 &box, int cells);

// Genus 2: the zero set of (x^2 (1 - x^2) - y^2)^2 + z^2 - r^2, a tube around the figure
// eight y^2 = x^2 (1 - x^2) (two loops crossing at the origin) in [-1.2, 1.2] x [-0.8, 0.8]
// x [-0.4, 0.4], by vcglib's marching cubes on `cells` cells along x; outward-oriented.
void MakeDoubleTorus(Mesh &m, double r = 0.1, int cells = 96);

} // namespace eulermap::testing

#include "core/pipeline.h"

#include <vector>

namespace eulermap::testing {

// Anchor pairs from two MeshLab picked-points files, matched by point name (a plain
// reader for the tests; the plugin reads .pp files with Qt's XML reader).
std::vector<AnchorPair> ReadAnchorPairs(const std::string &sourcePP, const std::string &targetPP);

// `count` anchor pairs for a target made vertex by vertex from the source (same vertex
// order): farthest-point samples among the source's vertices, each paired with the same
// vertex of the target. Farthest points are extremities, so many lie on tips.
std::vector<AnchorPair> FarthestPointAnchors(const Mesh &source, const Mesh &target, int count);

} // namespace eulermap::testing
