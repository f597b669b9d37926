#include "options.h"

#include <cmath>
#include <sstream>

namespace eulermap {

namespace {

std::string Number(double x) {
  std::ostringstream o;
  o << x;
  return o.str();
}

// in:  name (as the hosts call the parameter), value, [low, high], whether low itself is
//      allowed, what suits most meshes
// out: throws Error when value is not finite or out of range
void Check(const char *name, double value, double low, double high, bool lowAllowed, const char *hint) {
  const bool ok = std::isfinite(value) && (lowAllowed ? value >= low : value > low) && value <= high;
  if (!ok)
    throw Error(std::string(name) + " " + Number(value) + " is out of range: give a number " +
                (lowAllowed ? "from " : "above ") + Number(low) + (lowAllowed ? " to " : " up to ") + Number(high) +
                " (" + hint + ")");
}

} // namespace

void Options::Validate() const {
  if (gridNodes == vcg::Point3i(0, 0, 0))
    Check("grid_resolution", gridResolution, kMinGrid, kMaxGrid, true,
          "cells on the longest axis; 64 suits most meshes");
  else if (gridNodes.X() < 2 || gridNodes.Y() < 2 || gridNodes.Z() < 2)
    throw Error("grid nodes: give at least 2 nodes on every axis");
  Check("steps", steps, 1, kMaxSteps, true, "time steps; 40 suits most meshes");
  Check("alpha", alpha, 0, kMaxAlpha, false, "the smoothness weight; 2 suits most meshes");
  Check("hole_radius", holeRadius, 0, kMaxHoleRadius, false, "in grid cells; 1 is the default");
  Check("anchor weight", anchorWeight, 0, kMaxAnchorWeight, true, "0 is the paper's Eq. 2; 10 is the default");
  Check("anchor radius", anchorRadius, 0, kMaxAnchorRadius, false, "in grid cells; 3 is the default");
  Check("tolerance", tolerance, 0, 0.5, false, "relative residual of a velocity solve; 1e-4 is the default");
  Check("iterations", maxIterations, 1, kMaxIterationsLimit, true, "per velocity solve; 500 is the default");
  Check("threads", threads, 0, kMaxThreads, true, "0 uses every core");
}

} // namespace eulermap
