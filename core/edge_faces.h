// eulermap::EdgeFaces — the faces around each undirected edge of a triangle list, edges
// named by their two vertex indices in either order: which faces meet across an edge
// (input.cpp: orienting parts coherently; charts.cpp: texture seams; surgery.cpp: pieces of
// the tracked surface, rebuilt after every round of its cleaning).
//
// An open-addressing table: an edge's first two faces lie in its slot, the faces of an edge
// with more (non-manifold) in a list of their own. std::unordered_map with a vector for each
// edge allocated twice an edge, and surgery's cleaning, which rebuilds this table every
// round, was 70% of Table 1 row 2's deformation (docs/NOTES.md).
#pragma once

#include "mesh.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace eulermap {

class EdgeFaces {
 public:
  // The faces around an edge, in the order added; valid until the next Add or Clear.
  class Faces {
   public:
    Faces(const int *begin, const int *end) : begin_(begin), end_(end) {}
    const int *begin() const { return begin_; }
    const int *end() const { return end_; }
    std::size_t size() const { return std::size_t(end_ - begin_); }
    int operator[](std::size_t n) const { return begin_[n]; }

   private:
    const int *begin_, *end_;
  };

  // Room for the edges of about `faces` faces of a closed mesh (more grow the table).
  explicit EdgeFaces(std::size_t faces = 0) { Grow(faces * 3 / 2); }
  // The live faces of `mesh`, by face index; vertices by index.
  explicit EdgeFaces(const Mesh &mesh) : EdgeFaces(mesh.face.size()) {
    for (std::size_t n = 0; n < mesh.face.size(); ++n)
      if (!mesh.face[n].IsD())
        for (int e = 0; e < 3; ++e)
          Add(int(vcg::tri::Index(mesh, mesh.face[n].cV(e))), int(vcg::tri::Index(mesh, mesh.face[n].cV((e + 1) % 3))),
              int(n));
  }

  // Face `face` has the edge (a, b).
  void Add(int a, int b, int face) {
    if (2 * (edges_ + 1) > slots_.size()) Grow(2 * (edges_ + 1));
    Slot &s = slots_[Find(Key(a, b))];
    if (s.key == kEmpty) {
      s.key = Key(a, b), s.face[0] = face, ++edges_;
    } else if (s.face[1] == kOne) {
      s.face[1] = face;
    } else {
      if (s.face[1] >= 0) {  // a third face: the edge's faces move to a list of their own
        more_.push_back({s.face[0], s.face[1]});
        s.face[1] = kMore - int(more_.size() - 1);
      }
      more_[kMore - s.face[1]].push_back(face);
    }
  }

  // The faces added with the edge (a, b) or (b, a).
  Faces Around(int a, int b) const {
    const Slot &s = slots_[Find(Key(a, b))];
    if (s.key == kEmpty) return Faces(nullptr, nullptr);
    if (s.face[1] >= kOne) return Faces(s.face, s.face + (s.face[1] == kOne ? 1 : 2));
    const std::vector<int> &all = more_[kMore - s.face[1]];
    return Faces(all.data(), all.data() + all.size());
  }

  // No edges, the table's room kept.
  void Clear() {
    std::fill(slots_.begin(), slots_.end(), Slot());
    more_.clear();
    edges_ = 0;
  }

  // One number per undirected edge.
  static std::uint64_t Key(int a, int b) {
    if (a > b) std::swap(a, b);
    return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
  }

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t(0);  // Key of no pair of indices
  // face[1]: the second face, kOne when the edge has one, kMore - i when it has more than two
  // (all of them in more_[i]).
  static constexpr int kOne = -1, kMore = -2;
  struct Slot {
    std::uint64_t key = kEmpty;
    int face[2] = {-1, kOne};
  };

  // The slot of `key`, or the empty one where it would go: Fibonacci hashing, linear probing.
  std::size_t Find(std::uint64_t key) const {
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = (key * 0x9E3779B97F4A7C15ull) >> shift_;; i = (i + 1) & mask)
      if (slots_[i].key == key || slots_[i].key == kEmpty) return i;
  }

  // At least `edges` slots, a power of two; the edges kept.
  void Grow(std::size_t edges) {
    std::size_t size = 16;
    while (size < edges) size *= 2;
    if (size <= slots_.size()) return;
    std::vector<Slot> old(size);
    old.swap(slots_);
    for (shift_ = 64; (std::size_t(1) << (64 - shift_)) < size;) --shift_;
    for (const Slot &s : old)
      if (s.key != kEmpty) slots_[Find(s.key)] = s;
  }

  std::vector<Slot> slots_;
  int shift_ = 60;  // 64 - log2(slots_.size())
  std::size_t edges_ = 0;
  std::vector<std::vector<int>> more_;
};

} // namespace eulermap
