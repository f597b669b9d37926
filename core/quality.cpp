#include "quality.h"

#include <vcg/complex/algorithms/point_sampling.h>
#include <vcg/complex/algorithms/update/normal.h>

#include <cmath>

namespace eulermap {

double OnSurfaceRate(const std::vector<Point3> &points, const ClosestPoint &surface, double tolerance) {
  if (points.empty()) return 1;
  long inside = 0;
#pragma omp parallel for reduction(+ : inside) schedule(static)
  for (long n = 0; n < long(points.size()); ++n) {
    const ClosestHit hit = surface.Query(points[n], 2 * tolerance);
    inside += hit.face != nullptr && hit.distance <= tolerance;
  }
  return double(inside) / points.size();
}

double Coverage(Mesh &target, Mesh &mapped, double tolerance, int samples) {
  std::vector<Point3> points;
  vcg::tri::TrivialSampler<Mesh> sampler(points);
  vcg::tri::SurfaceSampling<Mesh, vcg::tri::TrivialSampler<Mesh>>::SamplingRandomGenerator().initialize(20161121);
  vcg::tri::SurfaceSampling<Mesh, vcg::tri::TrivialSampler<Mesh>>::Montecarlo(target, sampler, samples);
  const ClosestPoint index(mapped);
  return OnSurfaceRate(points, index, tolerance);
}

double FlippedAreaShare(Mesh &mapped, const ClosestPoint &target) {
  vcg::tri::UpdateNormal<Mesh>::PerFaceNormalized(mapped);
  double flipped = 0, total = 0;
#pragma omp parallel for reduction(+ : flipped, total) schedule(static)
  for (long n = 0; n < long(mapped.face.size()); ++n) {
    const Face &f = mapped.face[n];
    if (f.IsD()) continue;
    const double area = vcg::DoubleArea(f) / 2;
    const ClosestHit hit = target.Query(vcg::Barycenter(f));
    total += area;
    if (hit.face && f.cN() * hit.face->cN() < 0) flipped += area;
  }
  return total > 0 ? flipped / total : 0;
}

double LongestEdge(const Mesh &m) {
  double longest = 0;
  for (const Face &f : m.face)
    if (!f.IsD())
      for (int e = 0; e < 3; ++e) longest = std::max(longest, vcg::Distance(f.cP(e), f.cP((e + 1) % 3)));
  return longest;
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
