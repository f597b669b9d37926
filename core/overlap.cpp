#include "overlap.h"

#include "eigen_point.h"
#include "grid.h"
#include "sdf.h"
#include "parallel.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace eulermap {

namespace {

// A mesh's soft occupancy on its coarse grid (overlap.h).
struct Occupancy {
  Grid grid;
  std::vector<float> o;
  double volume = 0;  // the integral of o

  Occupancy(const Mesh &mesh, int cells) : grid(Grid::Enclosing(mesh.bbox, cells, 2)) {
    const ScalarField f = SignedDistance(mesh, grid);
    const double w = grid.h;
    o.resize(f.values.size());
    double sum = 0;
    for (std::size_t n = 0; n < o.size(); ++n) sum += o[n] = float(std::clamp(0.5 - f.values[n] / (2 * w), 0.0, 1.0));
    volume = sum * grid.h * grid.h * grid.h;
  }

  // Trilinear; 0 outside the grid (its two cells of padding read 0 already).
  double At(const Point3 &p) const {
    const Point3 g = grid.ToGrid(p);
    const int i = int(std::floor(g.X())), j = int(std::floor(g.Y())), k = int(std::floor(g.Z()));
    if (i < 0 || j < 0 || k < 0 || i + 1 >= grid.dims.X() || j + 1 >= grid.dims.Y() || k + 1 >= grid.dims.Z()) return 0;
    const double x = g.X() - i, y = g.Y() - j, z = g.Z() - k;
    const std::size_t sx = 1, sy = grid.dims.X(), sz = sy * grid.dims.Y(), n = grid.Index(i, j, k);
    auto lerp = [](double a, double b, double s) { return a + (b - a) * s; };
    const double c00 = lerp(o[n], o[n + sx], x), c10 = lerp(o[n + sy], o[n + sy + sx], x);
    const double c01 = lerp(o[n + sz], o[n + sz + sx], x), c11 = lerp(o[n + sz + sy], o[n + sz + sy + sx], x);
    return lerp(lerp(c00, c10, y), lerp(c01, c11, y), z);
  }
};

struct Sample {
  Point3 p;
  double o;
};

std::vector<Sample> Samples(const Occupancy &occupancy) {
  std::vector<Sample> samples;
  occupancy.grid.ForEachNode([&](int i, int j, int k, std::size_t n) {
    if (occupancy.o[n] > 0) samples.push_back({occupancy.grid.Node(i, j, k), occupancy.o[n]});
  });
  return samples;
}

struct Candidate {
  double scale;
  Point3 translation;
};

// The two meshes' occupancies at one resolution, and IoU(P) of overlap.h for P(p) = scale p +
// translation: the target's occupancy read at P^-1 x.
struct Overlaps {
  Occupancy source, target;
  std::vector<Sample> samples;  // the source's nodes with o > 0
  Eigen::Matrix3d back;         // R^-1 = R^T, R the placement's rotation

  Overlaps(const Mesh &s, const Mesh &t, int cells, const Eigen::Matrix3d &rotation)
      : source(s, cells), target(t, cells), samples(Samples(source)), back(rotation.transpose()) {}

  double IoU(const Candidate &c) const {
    double sum = 0;
    for (const Sample &x : samples) sum += x.o * target.At(ToPoint(back * ToEigen((x.p - c.translation) / c.scale)));
    const double h = source.grid.h, intersection = sum * h * h * h;
    return intersection / (source.volume + c.scale * c.scale * c.scale * target.volume - intersection);
  }

  // The best of the candidates (the first of equal ones), and its IoU.
  std::pair<Candidate, double> Best(const std::vector<Candidate> &candidates) const {
    std::vector<double> iou(candidates.size());
    ParallelFor(long(candidates.size()), [&](long n) { iou[n] = IoU(candidates[n]); });
    const std::size_t best = std::max_element(iou.begin(), iou.end()) - iou.begin();
    return {candidates[best], iou[best]};
  }
};

} // namespace

Overlap FitOverlap(const Mesh &source, const Mesh &target, const Similarity &start) {
  const Candidate origin{start.scale, ToPoint(start.translation)};
  // The lattice, on the coarse grids: scales s_c 2^(i/8), translations every coarse cell
  // within the reach.
  const Overlaps coarse(source, target, kOverlapCoarseCells, start.rotation);
  const double hc = coarse.source.grid.h;
  const int reach = int(std::ceil(kOverlapReach * source.bbox.Diag() / hc));
  std::vector<Candidate> lattice;
  for (int i = -4; i <= 4; ++i)
    for (int z = -reach; z <= reach; ++z)
      for (int y = -reach; y <= reach; ++y)
        for (int x = -reach; x <= reach; ++x)
          lattice.push_back({origin.scale * std::exp2(i / 8.0), origin.translation + Point3(x, y, z) * hc});
  Candidate found = coarse.Best(lattice).first;
  // Around the best, on the fine grids: steps of one, a half and a quarter cell.
  const Overlaps fine(source, target, kOverlapCells, start.rotation);
  const double h = fine.source.grid.h;
  Overlap result;
  result.startIoU = fine.IoU(origin);
  double iou = fine.IoU(found);
  for (int level = 0; level < 3; ++level) {
    const double step = h / (1 << level), ratio = std::exp2(1.0 / (16 << level));
    for (int move = 0; move < kOverlapMoves; ++move) {  // to the best neighbour until none is better
      std::vector<Candidate> around;
      for (int i = -1; i <= 1; ++i)
        for (int z = -1; z <= 1; ++z)
          for (int y = -1; y <= 1; ++y)
            for (int x = -1; x <= 1; ++x)
              around.push_back({found.scale * std::pow(ratio, i), found.translation + Point3(x, y, z) * step});
      const auto [next, value] = fine.Best(around);
      if (value <= iou) break;
      found = next, iou = value;
    }
  }
  // Keep the start where nothing overlaps more (meshes that overlap nowhere near it).
  if (iou <= result.startIoU) found = origin, iou = result.startIoU;
  result.placement = start;
  result.placement.scale = found.scale;
  result.placement.translation = ToEigen(found.translation);
  result.bestIoU = iou;
  return result;
}

} // namespace eulermap
