// Disjoint sets (union_find.h) against a plain labelling: after random merges two elements
// share a representative exactly when a chain of merges joins them; Add makes a singleton;
// Merge takes y's representative.
#include "core/union_find.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

using namespace eulermap;

namespace {

TEST(UnionFind, RepresentativesAgreeWithALabellingAfterRandomMerges) {
  const int n = 500;
  UnionFind sets(n);
  std::vector<int> label(n);
  for (int x = 0; x < n; ++x) label[x] = x;
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> pick(0, n - 1);
  for (int m = 0; m < 300; ++m) {
    const int x = pick(rng), y = pick(rng);
    sets.Merge(x, y);
    const int from = label[x], to = label[y];
    for (int &l : label)
      if (l == from) l = to;
  }
  for (int x = 0; x < n; x += 7)
    for (int y = 0; y < n; y += 3) EXPECT_EQ(sets.Find(x) == sets.Find(y), label[x] == label[y]) << x << " " << y;
}

TEST(UnionFind, AddMakesASingletonAndMergeKeepsYsRepresentative) {
  UnionFind sets(3);
  EXPECT_EQ(sets.Add(), 3);
  EXPECT_EQ(sets.Size(), 4);
  EXPECT_EQ(sets.Find(3), 3);
  sets.Merge(0, 1);
  sets.Merge(1, 3);
  EXPECT_EQ(sets.Find(0), 3);
  EXPECT_EQ(sets.Find(1), 3);
  EXPECT_EQ(sets.Find(2), 2);
}

} // namespace
