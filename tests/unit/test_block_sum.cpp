// Unit tests of block_sum.h: a parallel sum whose bits do not depend on the thread count.
#include "core/block_sum.h"
#include "core/threads.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace eulermap {
namespace {

// Terms of mixed sizes, so that the order of the additions shows in the last bits.
std::vector<double> Terms() {
  std::vector<double> x(100003);
  for (std::size_t n = 0; n < x.size(); ++n) x[n] = std::sin(double(n)) * std::pow(10.0, double(n % 7) - 3);
  return x;
}

double Sum(const std::vector<double> &x, int threads) {
  const ThreadCount team(threads);
  return BlockSum(long(x.size()), [&](long begin, long end) {
    double s = 0;
    for (long n = begin; n < end; ++n) s += x[n];
    return s;
  });
}

TEST(BlockSum, OneAndTwoThreadsGiveTheSameBits) {
  const std::vector<double> x = Terms();
  EXPECT_EQ(Sum(x, 1), Sum(x, 2));
}

TEST(BlockSum, IsTheSumOfTheTerms) {
  const std::vector<double> x = Terms();
  long double exact = 0;
  for (double v : x) exact += v;
  EXPECT_NEAR(Sum(x, 2), double(exact), 1e-9 * std::abs(double(exact)) + 1e-9);
  EXPECT_EQ(BlockSum(0, [](long, long) { return 1.0; }), 0.0);  // no blocks for no terms
}

} // namespace
} // namespace eulermap
