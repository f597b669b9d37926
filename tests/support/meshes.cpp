#include "meshes.h"

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/create/marching_cubes.h>
#include <vcg/complex/algorithms/create/mc_trivial_walker.h>
#include <vcg/complex/algorithms/create/platonic.h>
#include <vcg/complex/algorithms/refine.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <wrap/io_trimesh/import.h>

#include <algorithm>
#include <functional>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace eulermap::testing {

namespace {
void Finish(Mesh &m) {
  vcg::tri::UpdateBounding<Mesh>::Box(m);
  vcg::tri::UpdateNormal<Mesh>::PerVertexNormalizedPerFace(m);
}
} // namespace

std::string DataMesh(const std::string &name) { return std::string(EULERMAP_SOURCE_DIR) + "/../shared/data/meshes/" + name; }
std::string SampleFile(const std::string &name) { return std::string(EULERMAP_SOURCE_DIR) + "/samples/" + name; }

namespace {
// Wavefront OBJ: v, vt and f statements (polygons as fans, wedge texture coordinates).
// vcglib's reader drops faces that name vertices declared further down the file, as
// spot.obj does, so the tests read OBJ files with this one.
void LoadObj(const std::string &path, Mesh &m) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::vector<Point3> positions;
  std::vector<vcg::Point2d> uvs;
  std::vector<std::vector<std::pair<int, int>>> faces;  // (vertex, texcoord), 0-based, -1 none
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string key;
    s >> key;
    if (key == "v") {
      Point3 p;
      s >> p[0] >> p[1] >> p[2];
      positions.push_back(p);
    } else if (key == "vt") {
      vcg::Point2d t;
      s >> t[0] >> t[1];
      uvs.push_back(t);
    } else if (key == "f") {
      std::vector<std::pair<int, int>> corners;
      for (std::string token; s >> token;) {
        const std::size_t slash = token.find('/');
        const int v = std::stoi(token.substr(0, slash));
        int t = 0;
        if (slash != std::string::npos && slash + 1 < token.size() && token[slash + 1] != '/') t = std::stoi(token.substr(slash + 1));
        corners.push_back({v - 1, t - 1});
      }
      faces.push_back(corners);
    }
  }
  m.Clear();
  vcg::tri::Allocator<Mesh>::AddVertices(m, positions.size());
  for (std::size_t n = 0; n < positions.size(); ++n) m.vert[n].P() = positions[n];
  for (const auto &corners : faces)
    for (std::size_t c = 1; c + 1 < corners.size(); ++c) {
      const std::pair<int, int> tri[3] = {corners[0], corners[c], corners[c + 1]};
      auto f = vcg::tri::Allocator<Mesh>::AddFace(m, tri[0].first, tri[1].first, tri[2].first);
      for (int k = 0; k < 3; ++k)
        if (tri[k].second >= 0) f->WT(k).P() = uvs.at(tri[k].second);
    }
}
} // namespace

void LoadMesh(const std::string &path, Mesh &m) {
  if (path.size() > 4 && path.substr(path.size() - 4) == ".obj") {
    LoadObj(path, m);
    vcg::tri::Clean<Mesh>::RemoveUnreferencedVertex(m);
    vcg::tri::Allocator<Mesh>::CompactEveryVector(m);
    Finish(m);
    return;
  }
  int mask = 0;
  const int err = vcg::tri::io::Importer<Mesh>::Open(m, path.c_str(), mask);
  if (err != 0 && vcg::tri::io::Importer<Mesh>::ErrorCritical(err))
    throw std::runtime_error("cannot load " + path + ": " + vcg::tri::io::Importer<Mesh>::ErrorMsg(err));
  vcg::tri::Clean<Mesh>::RemoveUnreferencedVertex(m);
  vcg::tri::Allocator<Mesh>::CompactEveryVector(m);
  Finish(m);
}

void MakeSphere(Mesh &m, const Point3 &centre, double radius, int subdivisions) {
  MakeEllipsoid(m, centre, Point3(radius, radius, radius), subdivisions);
}

void MakeEllipsoid(Mesh &m, const Point3 &centre, const Point3 &radii, int subdivisions) {
  m.Clear();
  vcg::tri::Sphere(m, subdivisions);
  for (auto &v : m.vert) {
    const Point3 d = v.P().Normalize();
    v.P() = centre + Point3(d.X() * radii.X(), d.Y() * radii.Y(), d.Z() * radii.Z());
  }
  Finish(m);
}

void MakeBox(Mesh &m, const Box3 &box, int cellsPerSide) {  // faces split in halves until fine enough
  m.Clear();
  if (cellsPerSide <= 1) {
    vcg::tri::Box(m, box);
  } else {
    vcg::tri::Box(m, box);
    for (int s = 1; s < cellsPerSide; s *= 2) {
      vcg::tri::UpdateTopology<Mesh>::FaceFace(m);
      vcg::tri::Refine<Mesh, vcg::tri::MidPoint<Mesh>>(m, vcg::tri::MidPoint<Mesh>(&m), 0);
    }
  }
  vcg::tri::Clean<Mesh>::RemoveDuplicateVertex(m);
  vcg::tri::Allocator<Mesh>::CompactEveryVector(m);
  Finish(m);
}

void RefineMidpoint(Mesh &m, int times) {
  for (int r = 0; r < times; ++r) {
    vcg::tri::UpdateTopology<Mesh>::FaceFace(m);
    vcg::tri::Refine<Mesh, vcg::tri::MidPoint<Mesh>>(m, vcg::tri::MidPoint<Mesh>(&m), 0);
  }
  vcg::tri::Allocator<Mesh>::CompactEveryVector(m);
  Finish(m);
}

Point3 Bend(const Point3 &p, const Box3 &box, double strength) {
  const Point3 q = (p - box.Center()) / box.Diag();
  const double s = strength;
  const Point3 bent((1 + 0.3 * s) * q.X(), (1 - 0.2 * s) * q.Y() + 0.6 * s * q.X() * q.X(), q.Z() + 0.3 * s * q.Y() * q.X());
  const double cos = std::cos(0.4 * s), sin = std::sin(0.4 * s);
  return Point3(cos * bent.X() - sin * bent.Z(), bent.Y(), sin * bent.X() + cos * bent.Z()) * box.Diag();
}

void MakeImplicit(Mesh &m, const std::function<double(const Point3 &)> &f, const Box3 &box, int cells) {
  using Volume = vcg::SimpleVolume<vcg::SimpleVoxel<float>>;
  // vcglib 2020.09's TrivialWalker allocates its five slice buffers in SetExtractionBox
  // (new[]) and has no destructor; this one frees them (NextYSlice only swaps them).
  struct Walker : vcg::tri::TrivialWalker<Mesh, Volume> {
    Walker() { _x_cs = _y_cs = _z_cs = _x_ns = _z_ns = nullptr; }
    ~Walker() {
      for (int *buffer : {_x_cs, _y_cs, _z_cs, _x_ns, _z_ns}) delete[] buffer;
    }
  };
  using Cubes = vcg::tri::MarchingCubes<Mesh, Walker>;
  const double h = std::max({box.DimX(), box.DimY(), box.DimZ()}) / cells;
  const vcg::Point3i size(int(std::ceil(box.DimX() / h)) + 1, int(std::ceil(box.DimY() / h)) + 1,
                          int(std::ceil(box.DimZ() / h)) + 1);
  Volume volume;
  volume.Init(size, vcg::Box3<float>(vcg::Point3f::Construct(box.min),
                                     vcg::Point3f::Construct(box.min + Point3(size[0] - 1, size[1] - 1, size[2] - 1) * h)));
  for (int k = 0; k < size[2]; ++k)
    for (int j = 0; j < size[1]; ++j)
      for (int i = 0; i < size[0]; ++i) volume.Val(i, j, k) = float(f(box.min + Point3(i, j, k) * h));
  m.Clear();
  Walker walker;
  Cubes cubes(m, walker);
  walker.BuildMesh<Cubes>(m, volume, cubes, 0);
  vcg::tri::Clean<Mesh>::RemoveDuplicateVertex(m);
  vcg::tri::Clean<Mesh>::RemoveDegenerateFace(m);
  vcg::tri::Clean<Mesh>::RemoveUnreferencedVertex(m);
  vcg::tri::Allocator<Mesh>::CompactEveryVector(m);
  Finish(m);
}

void MakeDoubleTorus(Mesh &m, double r, int cells) {
  MakeImplicit(
      m,
      [r](const Point3 &p) {
        const double e = p.X() * p.X() * (1 - p.X() * p.X()) - p.Y() * p.Y();
        return e * e + p.Z() * p.Z() - r * r;
      },
      Box3(Point3(-1.2, -0.8, -0.4), Point3(1.2, 0.8, 0.4)), cells);
}

void MakeTorus(Mesh &m, const Point3 &centre, double R, double r, int ringDiv, int tubeDiv, TexCoordKind texCoords) {
  m.Clear();
  // Grid (i, j), i along the ring, j around the tube; with doubled seams i = ringDiv and
  // j = tubeDiv are vertices of their own, else they wrap to 0.
  const bool split = texCoords == TexCoordKind::PerVertex;
  const int ni = ringDiv + split, nj = tubeDiv + split;
  vcg::tri::Allocator<Mesh>::AddVertices(m, ni * nj);
  for (int i = 0; i < ni; ++i)
    for (int j = 0; j < nj; ++j) {
      const double u = 2 * M_PI * i / ringDiv, v = 2 * M_PI * j / tubeDiv;
      auto &vert = m.vert[i * nj + j];
      vert.P() = centre + Point3((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
      if (split) vert.T().P() = vcg::Point2d(double(i) / ringDiv, double(j) / tubeDiv);
    }
  auto id = [&](int i, int j) { return split ? i * nj + j : (i % ringDiv) * nj + j % tubeDiv; };
  for (int i = 0; i < ringDiv; ++i)
    for (int j = 0; j < tubeDiv; ++j) {
      const int corners[2][3][2] = {{{i, j}, {i + 1, j}, {i + 1, j + 1}}, {{i, j}, {i + 1, j + 1}, {i, j + 1}}};
      for (const auto &tri : corners) {
        auto f = vcg::tri::Allocator<Mesh>::AddFace(m, &m.vert[id(tri[0][0], tri[0][1])], &m.vert[id(tri[1][0], tri[1][1])],
                                                    &m.vert[id(tri[2][0], tri[2][1])]);
        if (texCoords == TexCoordKind::PerWedge)
          for (int c = 0; c < 3; ++c) f->WT(c).P() = vcg::Point2d(double(tri[c][0]) / ringDiv, double(tri[c][1]) / tubeDiv);
      }
    }
  Finish(m);
}

} // namespace eulermap::testing

#include <fstream>
#include <map>
#include <regex>
#include <sstream>

namespace eulermap::testing {

namespace {
std::map<std::string, Point3> ReadPickedPoints(const std::string &path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  std::map<std::string, Point3> points;
  const std::regex point("<point\\b[^>]*>");
  auto attribute = [](const std::string &tag, const std::string &name) {
    std::smatch m;
    if (!std::regex_search(tag, m, std::regex("\\b" + name + "=\"([^\"]*)\""))) return std::string();
    return m[1].str();
  };
  for (auto it = std::sregex_iterator(s.begin(), s.end(), point); it != std::sregex_iterator(); ++it) {
    const std::string tag = it->str();
    if (attribute(tag, "active") == "0") continue;
    points[attribute(tag, "name")] = Point3(std::stod(attribute(tag, "x")), std::stod(attribute(tag, "y")), std::stod(attribute(tag, "z")));
  }
  return points;
}
} // namespace

std::vector<AnchorPair> ReadAnchorPairs(const std::string &sourcePP, const std::string &targetPP) {
  const auto a = ReadPickedPoints(sourcePP), b = ReadPickedPoints(targetPP);
  std::vector<AnchorPair> pairs;
  for (const auto &[name, p] : a) {
    auto q = b.find(name);
    if (q == b.end()) throw std::runtime_error("anchor " + name + " is in " + sourcePP + " only");
    pairs.push_back({p, q->second, name});
  }
  if (pairs.size() != b.size()) throw std::runtime_error(targetPP + " has anchors that " + sourcePP + " lacks");
  return pairs;
}

std::vector<AnchorPair> FarthestPointAnchors(const Mesh &source, const Mesh &target, int count) {
  std::vector<AnchorPair> anchors;
  if (count == 0) return anchors;
  std::vector<double> distance(source.vert.size(), 1e300);
  std::size_t next = 0;
  for (int a = 0; a < count; ++a) {
    anchors.push_back({source.vert[next].cP(), target.vert[next].cP(), "a" + std::to_string(a)});
    for (std::size_t v = 0; v < source.vert.size(); ++v)
      distance[v] = std::min(distance[v], vcg::Distance(source.vert[v].cP(), source.vert[next].cP()));
    next = std::max_element(distance.begin(), distance.end()) - distance.begin();
  }
  return anchors;
}

} // namespace eulermap::testing
