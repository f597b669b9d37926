// eulermap::UnionFind — disjoint sets of the integers 0..Size()-1 (union-find with path
// halving): anchors joined by tetrahedra (morph.cpp), faces or points in one part
// (input.cpp, quality.cpp), labels of one component of the inside set (zero_set_topology.cpp).
#pragma once

#include <numeric>
#include <vector>

namespace eulermap {

class UnionFind {
 public:
  explicit UnionFind(int n = 0) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }

  int Size() const { return int(parent_.size()); }

  // A new set holding only the new element Size(); returns it.
  int Add() {
    parent_.push_back(Size());
    return parent_.back();
  }

  // The representative of x's set (the same for every element of it until the next Merge).
  int Find(int x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }

  // x's set and y's become one, represented by y's representative.
  void Merge(int x, int y) { parent_[Find(x)] = Find(y); }

 private:
  std::vector<int> parent_;
};

} // namespace eulermap
