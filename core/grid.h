// eulermap::Grid — the regular lattice of nodes on which f0, f1, f(.,t) and V live.
//
// Nodes are at origin + h * (i, j, k), 0 <= i < dims.X() etc.; node (i,j,k) is stored
// at index i + dims.X() * (j + dims.Y() * k).
#pragma once

#include "mesh.h"

#include <cstddef>

namespace eulermap {

struct Grid {
  Point3 origin = Point3(0, 0, 0);  // position of node (0,0,0)
  double h = 1;           // node spacing (one grid cell)
  vcg::Point3i dims = vcg::Point3i(0, 0, 0);  // node counts per axis

  // The common box of `box`, padded by `padCells` cells on every side, with
  // `cellsOnLongestAxis` cells across the box's longest side (DESIGN.md: grid.h).
  static Grid Enclosing(const Box3 &box, int cellsOnLongestAxis, double padCells = 3);

  // A grid with given node counts, spread over `box` (the bench's Table 1 shapes).
  // The spacing is the largest that fits the box into the nodes, padding included.
  static Grid WithNodes(const Box3 &box, vcg::Point3i nodes, double padCells = 3);

  std::size_t NodeCount() const { return std::size_t(dims.X()) * dims.Y() * dims.Z(); }
  std::size_t Index(int i, int j, int k) const { return i + std::size_t(dims.X()) * (j + std::size_t(dims.Y()) * k); }
  vcg::Point3i Coordinates(std::size_t index) const {  // Index's inverse
    return vcg::Point3i(int(index % dims.X()), int(index / dims.X() % dims.Y()), int(index / (std::size_t(dims.X()) * dims.Y())));
  }
  Point3 Node(int i, int j, int k) const { return origin + Point3(i, j, k) * h; }
  Point3 ToGrid(const Point3 &p) const { return (p - origin) / h; }    // world -> fractional node coordinates
  Box3 Bounds() const { return Box3(origin, origin + Point3(dims.X() - 1, dims.Y() - 1, dims.Z() - 1) * h); }

  // Calls fn(i, j, k, index) for every node, in storage order.
  template <class Fn> void ForEachNode(Fn &&fn) const {
    for (int k = 0; k < dims.Z(); ++k)
      for (int j = 0; j < dims.Y(); ++j)
        for (int i = 0; i < dims.X(); ++i) fn(i, j, k, Index(i, j, k));
  }
};

} // namespace eulermap
