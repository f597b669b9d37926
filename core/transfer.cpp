#include "transfer.h"

#include "parallel.h"

#include <vcg/simplex/face/distance.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace eulermap {

namespace {

// The coordinates at barycentric weights w of a face.
vcg::TexCoord2d Interpolate(const Face &f, const Point3 &w, TexCoordKind kind) {
  vcg::TexCoord2d uv = CornerTexCoord(f, 0, kind);
  uv.P() = vcg::Point2d(0, 0);
  for (int k = 0; k < 3; ++k) uv.P() += CornerTexCoord(f, k, kind).P() * w[k];
  return uv;
}

// The faces of `target` reachable from face `seed` without crossing a seam, whose boxes
// meet `region`.
std::vector<int> LocalChart(const Mesh &target, const TexCoordSeams &seams, int seed, const Box3 &region) {
  std::vector<int> chart{seed};
  for (std::size_t k = 0; k < chart.size(); ++k)
    for (int g : seams.across[chart[k]]) {
      if (g < 0 || std::find(chart.begin(), chart.end(), g) != chart.end()) continue;
      Box3 box;
      for (int c = 0; c < 3; ++c) box.Add(target.face[g].cP(c));
      if (box.Collide(region)) chart.push_back(g);
    }
  return chart;
}

} // namespace

TexCoordPull PullTexCoords(Mesh &cut, const Mesh &target, TexCoordKind kind, const TexCoordSeams &seams,
                           const std::vector<ClosestHit> &hits) {
  TexCoordPull pull;
  pull.from = kind;
  if (pull.from == TexCoordKind::None) return pull;
  auto index = [&](const Face *f) { return int(f - &target.face[0]); };

  std::vector<double> imageArea(cut.face.size(), 0.0);  // per face (summed in order below: any thread count)
  std::vector<char> acrossSeam(cut.face.size(), 0);
  ParallelFor(long(cut.face.size()), [&](long n) {
    Face &f = cut.face[n];
    if (f.IsD()) return;
    const ClosestHit *hit[3];
    Box3 region;
    double grow = 0;
    for (int c = 0; c < 3; ++c) {
      hit[c] = &hits[vcg::tri::Index(cut, f.V(c))];
      region.Add(hit[c]->point);
      for (int e = 0; e < 3; ++e)
        grow = std::max(grow, vcg::Distance(hit[c]->face->cP(e), hit[c]->face->cP((e + 1) % 3)));
    }
    region.Offset(grow);

    // The chart: the local chart of one image's face that holds the most images.
    std::vector<int> chart;
    int held = -1;
    double outside = 0;
    for (int c = 0; c < 3 && held < 3; ++c) {
      std::vector<int> candidate = LocalChart(target, seams, index(hit[c]->face), region);
      int count = 0;
      double distance = 0;
      for (int k = 0; k < 3; ++k) {
        if (std::find(candidate.begin(), candidate.end(), index(hit[k]->face)) != candidate.end()) {
          ++count;
          continue;
        }
        double nearest = std::numeric_limits<double>::max();
        for (int g : candidate) nearest = std::min(nearest, vcg::Distance(hit[k]->point, vcg::Barycenter(target.face[g])));
        distance += nearest;
      }
      if (count > held || (count == held && distance < outside)) chart.swap(candidate), held = count, outside = distance;
    }
    imageArea[n] = vcg::DoubleArea(vcg::Triangle3<double>(hit[0]->point, hit[1]->point, hit[2]->point)) / 2;
    acrossSeam[n] = held < 3;

    for (int c = 0; c < 3; ++c) {
      if (std::find(chart.begin(), chart.end(), index(hit[c]->face)) != chart.end()) {
        f.WT(c) = Interpolate(*hit[c]->face, hit[c]->barycentric, pull.from);
        continue;
      }
      // Across the seam: the chart's face nearest to the image, its coordinates continued.
      const Face *nearest = nullptr;
      double best = std::numeric_limits<double>::max();
      Point3 q;
      for (int g : chart)
        if (vcg::face::PointDistanceBase(target.face[g], hit[c]->point, best, q)) nearest = &target.face[g];
      f.WT(c) = Interpolate(*nearest, Barycentric(nearest->cP(0), nearest->cP(1), nearest->cP(2), hit[c]->point),
                            pull.from);
    }
  });
  double area = 0, areaAcross = 0;
  for (std::size_t n = 0; n < imageArea.size(); ++n)
    area += imageArea[n], areaAcross += acrossSeam[n] ? imageArea[n] : 0, pull.facesAcrossSeams += acrossSeam[n];
  pull.areaAcrossSeams = area > 0 ? areaAcross / area : 0;
  cut.textures = target.textures;
  return pull;
}

void PullVertexAttributes(Mesh &cut, const std::vector<ClosestHit> &hits, bool colour, bool quality) {
  for (std::size_t n = 0; n < cut.vert.size(); ++n) {
    Vertex &v = cut.vert[n];
    if (v.IsD()) continue;
    const Face &f = *hits[n].face;
    const Point3 &w = hits[n].barycentric;
    if (colour)  // rounded per channel (vcglib's Color4b::lerp truncates: 50 everywhere could read 49)
      for (int k = 0; k < 4; ++k) {
        const double c = w[0] * f.cV(0)->cC()[k] + w[1] * f.cV(1)->cC()[k] + w[2] * f.cV(2)->cC()[k];
        v.C()[k] = (unsigned char)std::lround(std::clamp(c, 0.0, 255.0));
      }
    if (quality) v.Q() = w[0] * f.cV(0)->cQ() + w[1] * f.cV(1)->cQ() + w[2] * f.cV(2)->cQ();
  }
}

} // namespace eulermap
