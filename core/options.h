// eulermap::Options — what the user can set, checked by Options::Validate against the
// limits of the parameter table (parameters.h), and the types every host hands to the
// pipeline: AnchorPair, Error.
#pragma once

#include "mesh.h"
#include "placement.h"
#include "velocity.h"

#include <stdexcept>
#include <string>

namespace eulermap {

// A message for the user: bad input, a run that does not fit, or cancellation.
struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct AnchorPair {
  Point3 source;  // a_i, on M0
  Point3 target;  // b_i, on M1 (its own frame)
  std::string name;
};

struct Options {
  int gridResolution = 64;   // cells on the longest axis of the common box
  vcg::Point3i gridNodes = vcg::Point3i(0, 0, 0);  // if set: exactly these node counts (benchmark)
  int steps = 40;            // time steps from t = 0 to 1
  double alpha = 2;          // smoothness weight of Eq. 2
  double holeRadius = 1;     // sphere radius around a saddle, in grid cells
  double anchorWeight = 10;  // beta at an anchor: pull of its motion on V (velocity.h); 0: the paper's Eq. 2
  double anchorRadius = 3;   // reach of that pull, in grid cells
  Align align = Align::CentreAndScale;  // placement when there are no anchors
  VelocitySolver::Method solver = VelocitySolver::Method::Multigrid;
  double tolerance = 1e-4;   // relative residual that ends a velocity solve
  int maxIterations = 500;   // per step
  bool untangle = true;      // relax folded places of the map on the target (untangle.h)
  bool fillHoles = false;
  bool transferTexture = true;   // the target's texture coordinates onto the cut (transfer.h)
  bool transferColour = false;   // the target's vertex colours onto the cut
  bool transferQuality = false;  // the target's vertex quality onto the cut, instead of the distortion
  int threads = 0;           // 0: OMP_NUM_THREADS, else the machine's cores (threads.h)

  // Throws Error naming the parameter (as the hosts call it), its value and the range to give.
  void Validate() const;
};

} // namespace eulermap
