// Options::Validate (options.h): the defaults pass; a value just outside each limit of the
// parameter table (parameters.h) is refused with the parameter's name, each limit itself
// is accepted, the message says the range and the default; explicit grid nodes replace
// grid_resolution and need 2 nodes on every axis.
#include "core/parameters.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace eulermap;

namespace {

bool Numeric(const Parameter &p) { return p.get && (p.kind == ParameterKind::Int || p.kind == ParameterKind::Float); }

TEST(Options, TheDefaultsPass) { EXPECT_NO_THROW(Options().Validate()); }

// Validate's message for `options`, empty when it accepts them.
std::string Refusal(const Options &options) {
  try {
    options.Validate();
  } catch (const Error &e) {
    return e.what();
  }
  return "";
}

TEST(Options, ValidateRefusesAValueJustOutsideEachLimit) {
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

TEST(Options, ValidateAcceptsEachLimitItself) {
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

TEST(Options, TheMessageSaysTheRangeAndTheDefault) {
  Options o;
  o.gridResolution = 2;
  EXPECT_EQ(Refusal(o), "grid_resolution 2 is out of range: give a number from 8 to 4096 (cells on the longest axis; "
                        "64 is the default)");
}

// The benchmark's exact node counts: grid_resolution is then not checked, but every axis
// needs 2 nodes.
TEST(Options, ExplicitGridNodesReplaceTheResolutionAndNeedTwoPerAxis) {
  Options o;
  o.gridResolution = 1;  // out of range, but not used
  o.gridNodes = vcg::Point3i(2, 40, 3);
  EXPECT_EQ(Refusal(o), "");
  o.gridNodes = vcg::Point3i(2, 1, 3);
  EXPECT_EQ(Refusal(o), "grid nodes: give at least 2 nodes on every axis");
  o.gridNodes = vcg::Point3i(2, 2, 2);
  o.steps = 0;  // the other limits still hold
  EXPECT_EQ(Refusal(o).rfind("steps ", 0), 0u) << Refusal(o);
}

} // namespace
