// eulermap::RedBlackLayout, eulermap::RedBlackArrays — how a multigrid level (multigrid.h)
// stores values at its nodes: split by colour (red: i + j + k even, black: odd), one array
// per colour and per component, with a ghost layer of zeros around the grid. A red-black
// Gauss-Seidel sweep over one colour then reads and writes contiguous runs of floats, one
// run per grid row, with neighbours at fixed offsets and no bounds checks (vectorised).
//
// Storage coordinates are s = (i, j, k) + 1 inside padded sizes P_a = d_a + 3 (P_x rounded
// up to even): one ghost layer below, two above, as the full-weighting restriction of
// multigrid.h reads one node past a coarse node that lies one fine cell past the box. Node
// s has storage index L = s_x + P_x (s_y + P_y s_z) and lies at position L / 2 of its
// colour's arrays: with P_x even, L = 2m and L = 2m + 1 are x-neighbours, of different
// colours. Along a row the nodes of one colour are at consecutive positions m; their
// neighbours (of the other colour) are at m + o and m + o + 1 in x (o = 0 when s_x is odd,
// -1 when it is even), m -/+ P_x / 2 in y and m -/+ P_x P_y / 2 in z.
#pragma once

#include "interrupt.h"
#include "mesh.h"
#include "parallel.h"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace eulermap {

struct RedBlackLayout {
  vcg::Point3i dims = vcg::Point3i(0, 0, 0);    // real nodes per axis
  vcg::Point3i padded = vcg::Point3i(0, 0, 0);  // P, ghosts included

  RedBlackLayout() = default;
  explicit RedBlackLayout(const vcg::Point3i &d) : dims(d), padded((d[0] + 4) & ~1, d[1] + 3, d[2] + 3) {}

  std::size_t Nodes() const { return std::size_t(dims[0]) * dims[1] * dims[2]; }  // real ones
  std::size_t Positions() const { return std::size_t(padded[0]) * padded[1] * padded[2] / 2; }  // per colour
  long RowStride() const { return padded[0] / 2; }
  long PlaneStride() const { return long(padded[0]) * padded[1] / 2; }
  static int Colour(int i, int j, int k) { return (i + j + k) & 1; }
  // Real neighbours of real node (i, j, k) (6 inside, fewer on the box's faces).
  int NeighbourCount(int i, int j, int k) const {
    return (i > 0) + (i + 1 < dims[0]) + (j > 0) + (j + 1 < dims[1]) + (k > 0) + (k + 1 < dims[2]);
  }
  // Position of real node (i, j, k), ghosts around the box included (-1 <= i <= d_x + 1).
  std::size_t Position(int i, int j, int k) const {
    return (std::size_t(i + 1) + std::size_t(padded[0]) * (std::size_t(j + 1) + std::size_t(padded[1]) * (k + 1))) / 2;
  }

  // The nodes of colour c in real row (j, k): i = firstI, firstI + 2, ..., count of them, at
  // positions first, first + 1, ...; their x-neighbours at m + west and m + west + 1.
  struct Run {
    int firstI, count;
    std::size_t first;
    long west;
  };
  Run RowRun(int c, int j, int k) const {
    Run run;
    run.firstI = (c + j + k) & 1;  // i = c - j - k (mod 2)
    run.count = std::max(0, (dims[0] - run.firstI + 1) / 2);
    run.first = Position(run.firstI, j, k);
    run.west = run.firstI ? -1 : 0;  // s_x = i + 1 even: L - 1 = 2m - 1 lies at m - 1
    return run;
  }
};

// N components of every node, in a RedBlackLayout: c[colour][component][position]. Ghost
// positions hold 0 and are never written (unless all positions are, with zeros there).
template <int N, class T = float> struct RedBlackArrays {
  std::vector<T> c[2][N];

  // Zeroed arrays for colours 0 .. colours - 1 (1: red only), the interrupt asked while
  // they are filled (AssignPolling).
  void Resize(const RedBlackLayout &layout, int colours = 2, const Interrupt &interrupt = Interrupt()) {
    for (int colour = 0; colour < colours; ++colour)
      for (std::vector<T> &a : c[colour]) AssignPolling(a, layout.Positions(), T(0), interrupt);
  }
};

// Grids of fewer nodes are worked on by one thread: starting and joining the threads costs
// more than the work (the multigrid's coarse levels; the coarsest one has 40 sweeps a cycle).
constexpr std::size_t kParallelNodes = 16384;

// Calls fn(j, k, c, run, row) for every run of colour c, firstColour <= c <= lastColour, in
// real row (j, k); row is the Grid::Index of node (0, j, k): the run's n-th node is
// i = run.firstI + 2n, at index row + i and at position run.first + n. Planes in parallel
// (from kParallelNodes nodes).
template <class Fn> void ForEachRun(const RedBlackLayout &layout, int firstColour, int lastColour, Fn &&fn) {
  const vcg::Point3i &d = layout.dims;
  ParallelFor(
      d[2],
      [&](long k) {
        for (int j = 0; j < d[1]; ++j)
          for (int c = firstColour; c <= lastColour; ++c)
            fn(j, int(k), c, layout.RowRun(c, j, int(k)), std::size_t(d[0]) * (j + std::size_t(d[1]) * k));
      },
      layout.Nodes() >= kParallelNodes);
}

// Sum of the six neighbours of the node at m of a run (run.west: its x-offset) in the other
// colour's array o, offset like the run (the ghosts stand in for missing neighbours).
template <class T> inline T NeighbourSum(const T *o, long m, long west, long hy, long hz) {
  return o[m + west] + o[m + west + 1] + o[m - hy] + o[m + hy] + o[m - hz] + o[m + hz];
}

} // namespace eulermap
