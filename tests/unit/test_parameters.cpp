// The parameter table (parameters.h): defaults inside their limits, every entry read and
// written through its Options member, and the .mlx element the samples and tests use.
// Options::Validate against the table's limits: test_options.
#include "core/parameters.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace eulermap;

namespace {

bool Numeric(const Parameter &p) { return p.get && (p.kind == ParameterKind::Int || p.kind == ParameterKind::Float); }

TEST(Parameters, DefaultsAreInsideTheirLimits) {
  for (const Parameter &p : Parameters())
    if (Numeric(p)) EXPECT_TRUE(p.InRange(p.Default())) << p.name;
}

TEST(Parameters, EachEntryWritesTheOptionItReads) {
  for (const Parameter &p : Parameters()) {
    if (!p.get) continue;
    Options o;
    const double other = p.kind == ParameterKind::Bool || p.kind == ParameterKind::Enum ? 1 - p.Default()
                                                                                      : (p.Default() + p.high) / 2;
    p.set(o, other);
    EXPECT_EQ(p.get(o), p.kind == ParameterKind::Int ? std::floor(other) : other) << p.name;
  }
}

TEST(Parameters, TheMlxElementGivesEveryFilterParameterInOrder) {
  const std::string mlx = MlxFilter({{"steps", "12"}, {"anchor_pairs", "1:2, 3:4"}});
  std::size_t at = 0;
  for (const Parameter &p : Parameters()) {
    if (!p.inFilter) {
      EXPECT_EQ(mlx.find(std::string("name=\"") + p.name + "\""), std::string::npos) << p.name;
      continue;
    }
    const std::size_t found = mlx.find(std::string("name=\"") + p.name + "\"", at);
    ASSERT_NE(found, std::string::npos) << p.name << " missing or out of order";
    at = found;
  }
  EXPECT_NE(mlx.find("name=\"steps\" value=\"12\""), std::string::npos);
  EXPECT_NE(mlx.find("name=\"grid_resolution\" value=\"64\""), std::string::npos);
  EXPECT_NE(mlx.find("name=\"target_mesh\" value=\"1\""), std::string::npos);
  EXPECT_THROW(MlxFilter({{"no_such_parameter", "1"}}), Error);
  EXPECT_THROW(MlxFilter({{"threads", "1"}}), Error) << "threads is not the filter's";
}

} // namespace
