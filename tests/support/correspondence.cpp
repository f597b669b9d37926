#include "tests/support/correspondence.h"

#include "core/closest.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <queue>
#include <stdexcept>
#include <tuple>

namespace eulermap::testing {

std::string TopkidsFile(const std::string &name) { return std::string(EULERMAP_SOURCE_DIR) + "/../shared/data/topkids/" + name; }

std::vector<int> ReadTruth(const std::string &path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::vector<std::pair<int, int>> pairs;
  for (int i, j; in >> i >> j;) pairs.push_back({i - 1, j - 1});
  std::vector<int> truth(pairs.size(), -1);
  for (const auto &[i, j] : pairs) truth.at(i) = j;
  return truth;
}

std::vector<int> FarthestVertices(const Mesh &m, int count) {
  std::vector<int> chosen;
  std::vector<double> distance(m.vert.size(), 1e300);
  int next = 0;
  while (int(chosen.size()) < std::min<int>(count, int(m.vert.size()))) {
    chosen.push_back(next);
    for (std::size_t v = 0; v < m.vert.size(); ++v)
      distance[v] = std::min(distance[v], vcg::Distance(m.vert[v].cP(), m.vert[next].cP()));
    next = int(std::max_element(distance.begin(), distance.end()) - distance.begin());
  }
  return chosen;
}

std::vector<Point3> SourceImages(const Mesh &source, Result &result, std::vector<char> *kept) {
  std::map<std::tuple<double, double, double>, int> at;
  for (std::size_t n = 0; n < result.cut.vert.size(); ++n) {
    const Point3 &p = result.cut.vert[n].cP();
    at.emplace(std::make_tuple(p.X(), p.Y(), p.Z()), int(n));
  }
  auto image = vcg::tri::Allocator<Mesh>::FindPerVertexAttribute<Point3>(result.cut, "TargetPosition");
  std::vector<Point3> images;
  if (kept) kept->assign(source.vert.size(), 0);
  for (std::size_t v = 0; v < source.vert.size(); ++v) {
    const Point3 &p = source.vert[v].cP();
    const auto found = at.find(std::make_tuple(p.X(), p.Y(), p.Z()));
    int n = found == at.end() ? -1 : found->second;
    if (n < 0) {
      double nearest = 1e300;
      for (std::size_t c = 0; c < result.cut.vert.size(); ++c)
        if (const double d = vcg::SquaredDistance(result.cut.vert[c].cP(), p); d < nearest) nearest = d, n = int(c);
    } else if (kept) {
      (*kept)[v] = 1;
    }
    images.push_back(image[n]);
  }
  return images;
}

std::vector<double> EdgePathLengths(const Mesh &surface, const std::vector<int> &from, const std::vector<int> &to) {
  const int n = int(surface.vert.size());
  std::vector<std::vector<std::pair<int, double>>> edges(n);
  for (const Face &f : surface.face)
    for (int c = 0; c < 3; ++c) {
      const int a = int(vcg::tri::Index(surface, f.cV(c))), b = int(vcg::tri::Index(surface, f.cV((c + 1) % 3)));
      const double l = vcg::Distance(f.cP(c), f.cP((c + 1) % 3));
      edges[a].push_back({b, l});
      edges[b].push_back({a, l});
    }
  std::vector<double> lengths;
  std::vector<double> d(n);
  for (std::size_t k = 0; k < from.size(); ++k) {  // Dijkstra from from[k], stopped at to[k]
    std::fill(d.begin(), d.end(), 1e300);
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    d[from[k]] = 0, queue.push({0.0, from[k]});
    while (!queue.empty()) {
      const auto [dist, v] = queue.top();
      queue.pop();
      if (v == to[k]) break;
      if (dist > d[v]) continue;
      for (const auto &[w, l] : edges[v])
        if (dist + l < d[w]) d[w] = dist + l, queue.push({d[w], w});
    }
    lengths.push_back(d[to[k]]);
  }
  return lengths;
}

} // namespace eulermap::testing
