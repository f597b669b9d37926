#include "quality.h"

#include "parallel.h"
#include "union_find.h"

#include <vcg/complex/algorithms/point_sampling.h>
#include <vcg/complex/algorithms/update/normal.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace eulermap {

namespace {

// Single-linkage groups of `points`: points closer than `link` share a group. A hash grid
// of cells `link` wide finds the pairs (each point against the 27 cells around its own).
std::vector<UncoveredPart> GroupPoints(const std::vector<Point3> &points, double link, std::size_t total) {
  UnionFind groups(int(points.size()));
  auto key = [&](long x, long y, long z) { return (x * 73856093L) ^ (y * 19349663L) ^ (z * 83492791L); };
  auto cellOf = [&](const Point3 &p, int a) { return long(std::floor(p[a] / link)); };
  std::unordered_map<long, std::vector<int>> cells;
  for (int i = 0; i < int(points.size()); ++i)
    cells[key(cellOf(points[i], 0), cellOf(points[i], 1), cellOf(points[i], 2))].push_back(i);
  for (int i = 0; i < int(points.size()); ++i)
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy)
        for (long dz = -1; dz <= 1; ++dz) {
          const auto it = cells.find(key(cellOf(points[i], 0) + dx, cellOf(points[i], 1) + dy, cellOf(points[i], 2) + dz));
          if (it == cells.end()) continue;
          for (int j : it->second)
            if (j > i && vcg::SquaredDistance(points[i], points[j]) < link * link) groups.Merge(i, j);
        }
  std::unordered_map<int, int> index;  // root -> part
  std::vector<UncoveredPart> parts;
  std::vector<std::vector<int>> members;
  for (int i = 0; i < int(points.size()); ++i) {
    const auto [it, added] = index.emplace(groups.Find(i), int(parts.size()));
    if (added) parts.push_back({Point3(0, 0, 0), 0, 0}), members.emplace_back();
    members[it->second].push_back(i);
  }
  for (std::size_t n = 0; n < parts.size(); ++n) {
    for (int i : members[n]) parts[n].centre += points[i] / double(members[n].size());
    for (int i : members[n]) parts[n].radius = std::max(parts[n].radius, vcg::Distance(points[i], parts[n].centre));
    parts[n].share = double(members[n].size()) / total;
  }
  std::stable_sort(parts.begin(), parts.end(), [](const UncoveredPart &a, const UncoveredPart &b) { return a.share > b.share; });
  return parts;
}

} // namespace

double OnSurfaceRate(const std::vector<Point3> &points, const ClosestPoint &surface, double tolerance) {
  if (points.empty()) return 1;
  std::vector<char> inside(points.size());
  ParallelFor(long(points.size()), [&](long n) {
    const ClosestHit hit = surface.Query(points[n], 2 * tolerance);
    inside[n] = hit.face != nullptr && hit.distance <= tolerance;
  });
  return double(std::count(inside.begin(), inside.end(), 1)) / points.size();
}

double Coverage(Mesh &target, Mesh &mapped, double tolerance, std::vector<UncoveredPart> *uncovered, int samples) {
  std::vector<Point3> points;
  vcg::tri::TrivialSampler<Mesh> sampler(points);
  vcg::tri::SurfaceSampling<Mesh, vcg::tri::TrivialSampler<Mesh>>::SamplingRandomGenerator().initialize(20161121);
  vcg::tri::SurfaceSampling<Mesh, vcg::tri::TrivialSampler<Mesh>>::Montecarlo(target, sampler, samples);
  if (points.empty()) return 1;
  const ClosestPoint index(mapped);
  std::vector<char> near(points.size());
  ParallelFor(long(points.size()), [&](long n) {
    const ClosestHit hit = index.Query(points[n], 2 * tolerance);
    near[n] = hit.face != nullptr && hit.distance <= tolerance;
  });
  std::vector<Point3> missed;
  for (std::size_t n = 0; n < points.size(); ++n)
    if (!near[n]) missed.push_back(points[n]);
  if (uncovered) *uncovered = GroupPoints(missed, tolerance, points.size());
  return 1 - double(missed.size()) / points.size();
}

double FlippedAreaShare(Mesh &mapped, const ClosestPoint &target) {
  vcg::tri::UpdateNormal<Mesh>::PerFaceNormalized(mapped);
  // Per face, its area and whether it is flipped, then summed in face order: the same bits
  // for any number of threads (a parallel sum would add in an order that depends on it).
  std::vector<double> area(mapped.face.size(), 0.0);
  std::vector<char> flipped(mapped.face.size(), 0);
  ParallelFor(long(mapped.face.size()), [&](long n) {
    const Face &f = mapped.face[n];
    if (f.IsD()) return;
    area[n] = vcg::DoubleArea(f) / 2;
    const ClosestHit hit = target.Query(vcg::Barycenter(f));
    flipped[n] = hit.face && f.cN() * hit.face->cN() < 0;
  });
  double flippedArea = 0, total = 0;
  for (std::size_t n = 0; n < area.size(); ++n) total += area[n], flippedArea += flipped[n] ? area[n] : 0;
  return total > 0 ? flippedArea / total : 0;
}

double LongestEdge(const Mesh &m) {
  double longest = 0;
  for (const Face &f : m.face)
    if (!f.IsD())
      for (int e = 0; e < 3; ++e) longest = std::max(longest, vcg::Distance(f.cP(e), f.cP((e + 1) % 3)));
  return longest;
}

double LongestStretchedEdge(const Mesh &cut, const Mesh &mapped, double scale, Point3 *midpoint) {
  double longest = 0;
  for (std::size_t f = 0; f < mapped.face.size(); ++f)
    if (!mapped.face[f].IsD())
      for (int e = 0; e < 3; ++e) {
        const Point3 &a = mapped.face[f].cP(e), &b = mapped.face[f].cP((e + 1) % 3);
        const double length = vcg::Distance(a, b);
        const double source = vcg::Distance(cut.face[f].cP(e), cut.face[f].cP((e + 1) % 3)) / scale;
        if (length > longest && length > kStretchFactor * source) longest = length, *midpoint = (a + b) / 2;
      }
  return longest;
}

double MeanEdgeLength(const Mesh &m) {
  double sum = 0;
  long edges = 0;
  for (const Face &f : m.face)
    if (!f.IsD())
      for (int e = 0; e < 3; ++e) sum += vcg::Distance(f.cP(e), f.cP((e + 1) % 3)), ++edges;
  return edges > 0 ? sum / edges : 0;
}

double StoreDistortion(Mesh &cut, const Mesh &mapped) {
  std::vector<double> areaSource(cut.vert.size(), 0), areaMapped(cut.vert.size(), 0);
  double totalSource = 0, totalMapped = 0;
  for (std::size_t n = 0; n < cut.face.size(); ++n) {
    if (cut.face[n].IsD()) continue;
    const double a0 = vcg::DoubleArea(cut.face[n]), a1 = vcg::DoubleArea(mapped.face[n]);
    totalSource += a0;
    totalMapped += a1;
    for (int c = 0; c < 3; ++c) {
      const std::size_t v = vcg::tri::Index(cut, cut.face[n].cV(c));
      areaSource[v] += a0;
      areaMapped[v] += a1;
    }
  }
  double sum = 0;
  int counted = 0;
  for (std::size_t v = 0; v < cut.vert.size(); ++v) {
    double q = 0;
    if (areaSource[v] > 0 && totalMapped > 0) {
      const double ratio = (areaMapped[v] / totalMapped) / (areaSource[v] / totalSource);
      q = std::abs(std::log2(std::max(ratio, 1e-12)));
      sum += q;
      ++counted;
    }
    cut.vert[v].Q() = q;
  }
  return counted ? sum / counted : 0;
}

} // namespace eulermap
