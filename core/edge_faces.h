// eulermap::EdgeFaces — the faces around each undirected edge of a triangle list, edges
// named by their two vertex indices in either order: which faces meet across an edge
// (input.cpp: orienting parts coherently; charts.cpp: texture seams; surgery.cpp: pieces of
// the tracked surface).
#pragma once

#include "mesh.h"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace eulermap {

class EdgeFaces {
 public:
  EdgeFaces() = default;
  // The live faces of `mesh`, by face index; vertices by index.
  explicit EdgeFaces(const Mesh &mesh) {
    for (std::size_t n = 0; n < mesh.face.size(); ++n)
      if (!mesh.face[n].IsD())
        for (int e = 0; e < 3; ++e)
          Add(int(vcg::tri::Index(mesh, mesh.face[n].cV(e))), int(vcg::tri::Index(mesh, mesh.face[n].cV((e + 1) % 3))),
              int(n));
  }

  // Face `face` has the edge (a, b).
  void Add(int a, int b, int face) { faces_[Key(a, b)].push_back(face); }

  // The faces added with the edge (a, b) or (b, a), in the order added.
  const std::vector<int> &Around(int a, int b) const {
    static const std::vector<int> kNone;
    const auto it = faces_.find(Key(a, b));
    return it == faces_.end() ? kNone : it->second;
  }

  // One number per undirected edge.
  static std::uint64_t Key(int a, int b) {
    if (a > b) std::swap(a, b);
    return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
  }

 private:
  std::unordered_map<std::uint64_t, std::vector<int>> faces_;
};

} // namespace eulermap
