// The parameter table (parameters.h): defaults inside their limits, Options::Validate
// refusing a value just outside each limit with the parameter's name, every entry read and
// written through its Options member, and the .mlx element the samples and tests use.
#include "core/parameters.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace eulermap;

namespace {

bool Numeric(const Parameter &p) { return p.get && (p.kind == ParameterKind::Int || p.kind == ParameterKind::Float); }

TEST(Parameters, DefaultsAreInsideTheirLimits) {
  for (const Parameter &p : Parameters())
    if (Numeric(p)) EXPECT_TRUE(p.InRange(p.Default())) << p.name;
  EXPECT_NO_THROW(Options().Validate());
}

// Validate's message for `options`, empty when it accepts them.
std::string Refusal(const Options &options) {
  try {
    options.Validate();
  } catch (const Error &e) {
    return e.what();
  }
  return "";
}

TEST(Parameters, ValidateRefusesAValueJustOutsideEachLimit) {
  for (const Parameter &p : Parameters()) {
    if (!Numeric(p)) continue;
    const double step = p.kind == ParameterKind::Int ? 1 : 1e-9 * std::max(1.0, std::abs(p.high));
    for (double outside : {p.high + step, p.lowIncluded ? p.low - step : p.low, std::numeric_limits<double>::quiet_NaN()}) {
      if (p.kind == ParameterKind::Int && std::isnan(outside)) continue;  // an int has no NaN
      Options o;
      p.set(o, outside);
      EXPECT_EQ(Refusal(o).rfind(std::string(p.name) + " ", 0), 0u) << p.name << " " << outside << ": " << Refusal(o);
    }
  }
}

TEST(Parameters, ValidateAcceptsEachLimitItself) {
  for (const Parameter &p : Parameters()) {
    if (!Numeric(p)) continue;
    Options o;
    p.set(o, p.high);
    EXPECT_EQ(Refusal(o), "") << p.name;
    if (p.lowIncluded) {
      p.set(o, p.low);
      EXPECT_EQ(Refusal(o), "") << p.name;
    }
  }
}

TEST(Parameters, TheMessageSaysTheRangeAndTheDefault) {
  Options o;
  o.gridResolution = 2;
  EXPECT_EQ(Refusal(o), "grid_resolution 2 is out of range: give a number from 8 to 4096 (cells on the longest axis; "
                        "64 is the default)");
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
