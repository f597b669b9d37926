// Correspondence on real scans with ground truth (../shared/data/topkids, the TOPKIDS
// protocol of ../shared/data/README.md), for the tests and the benchmark: where each source
// vertex goes, and how far that is from where it should go, along the target's surface.
#pragma once

#include "core/pipeline.h"

#include <string>
#include <vector>

namespace eulermap::testing {

// Path of a file in ../shared/data/topkids.
std::string TopkidsFile(const std::string &name);

// kidXX_ref.txt: per vertex of kidXX (0-based), its true vertex of kid00 (0-based).
std::vector<int> ReadTruth(const std::string &path);

// `count` farthest-point samples among m's vertices (Euclidean, from vertex 0).
std::vector<int> FarthestVertices(const Mesh &m, int count);

// The image of every vertex of `source` under the map in `result`: the TargetPosition of the
// cut vertex at its place (the cut keeps the source's positions), or where surgery removed
// the vertex, that of the nearest kept one; kept[n] says which.
std::vector<Point3> SourceImages(const Mesh &source, Result &result, std::vector<char> *kept = nullptr);

// Shortest paths along the edges of `surface` (an upper bound of the geodesic distance,
// about 1.1 times it on a fine triangulation), from vertex `from[n]` to vertex `to[n]`.
std::vector<double> EdgePathLengths(const Mesh &surface, const std::vector<int> &from, const std::vector<int> &to);

} // namespace eulermap::testing
