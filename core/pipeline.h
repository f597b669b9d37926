// eulermap::ComputeMap — the whole pipeline of DESIGN.md, from two meshes to the map.
//
//   in:  source M0, target M1 (left untouched), anchor pairs (points on each mesh),
//        Options, and a progress callback
//   out: Result: `cut` (the source minus the discs removed by surgery, original
//        positions, per-vertex attribute "TargetPosition" = F(p) on the real target,
//        per-vertex quality = distortion, wedge texture coordinates pulled from the
//        target when it has them, and on request its colour and quality: transfer.h),
//        `mapped` (same connectivity and vertex order, positions F(p), the source's own
//        texture coordinates and textures), `filled` (only with Options::fillHoles, a
//        copy of `cut` with its holes closed), and the Report.
// Throws eulermap::Error with a message for the user on bad input or cancellation.
#pragma once

#include "mesh.h"
#include "placement.h"
#include "report.h"
#include "velocity.h"

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace eulermap {

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
  int threads = 0;           // 0: all cores
  std::size_t maxGridNodes = 8u << 20;  // larger grids are refused (memory)
};

struct Result {
  Mesh cut;
  Mesh mapped;
  Mesh filled;
  std::vector<Point3> sampleImages;  // of ComputeMap's samples, in order
  Report report;
};

// Called with a share in [0,1] and the stage's name; return false to cancel.
using Progress = std::function<bool(double, const std::string &)>;

// samples: extra points on the source (or off it: each follows its own level set) to map
// with the integral formula (Eq. 7) beside the vertices; their images, on the target's
// frame and not projected onto it, go to Result::sampleImages.
void ComputeMap(Mesh &source, Mesh &target, const std::vector<AnchorPair> &anchors, const Options &options,
                Result &result, const Progress &progress = {}, const std::vector<Point3> &samples = {});

} // namespace eulermap
