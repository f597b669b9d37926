// eulermap::BlockSum — a parallel sum that gives the same bits for any number of threads.
//
// A reduction over the threads would add their partial sums in an order that depends on
// how many there are. Here the range is cut into fixed blocks, each summed by one thread in a fixed
// order (the block's own loops may be vectorised: their lanes are fixed by the build), and
// the blocks' sums are added in order. So maps made with 1 and 2 threads agree bit for bit
// (test_end_to_end).
#pragma once

#include "parallel.h"

#include <algorithm>
#include <numeric>
#include <vector>

namespace eulermap {

// in:  n, block(begin, end) returning the sum over [begin, end) (it may also write the
//      elements of its range: fused passes)
// out: the sum of block over fixed blocks of [0, n), in order
template <class Block> double BlockSum(long n, Block &&block) {
  constexpr long kBlock = 4096;
  const long blocks = (n + kBlock - 1) / kBlock;
  std::vector<double> partial(blocks);
  ParallelFor(blocks, [&](long k) { partial[k] = block(k * kBlock, std::min(n, (k + 1) * kBlock)); });
  return std::accumulate(partial.begin(), partial.end(), 0.0);
}

} // namespace eulermap
