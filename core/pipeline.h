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
// Stages, in order (pipeline.cpp): the meshes checked and placed, the grid, f0 and f1 (sdf.h),
// the morph (the linear blend of Eq. 1, warped by anchors, or grow_shrink.h where the blend
// would grow a part from nothing), the topology events along it (morph_topology.h) and the
// plan of which are cut (surgery_plan.h), the step loop (velocity, tracking, surgery), and
// the outputs with their figures. Where that map's figures fail, the other morphs are tried
// too (grow_shrink.h or the linear blend, then inflate_shrink.h; with a warp, the warp through
// the anchors and as many more read from the first map: pipeline.cpp, AddAnchorsFromMap) and
// the best map kept (Report::morphsTried).
// The inputs are checked and repaired on private copies first (input.h: what was repaired
// goes to Report::repairs); a run whose grid does not fit in the memory the process may
// have is refused before anything large is allocated (memory.h); a map whose own figures
// say it failed ends with Report::warnings that say what to change.
// Throws eulermap::Error with a message for the user on bad input, a run that does not
// fit, a result with no faces, or cancellation.
#pragma once

#include "mesh.h"
#include "options.h"
#include "report.h"

#include <functional>
#include <string>
#include <vector>

namespace eulermap {

struct Result {
  Mesh cut;
  Mesh mapped;
  Mesh filled;
  std::vector<Point3> sampleImages;  // of ComputeMap's samples, in order
  Report report;
};

// Called with a share in [0,1] and the stage's name; return false to cancel. Called at each
// stage, and again with the same share and name inside the long loops: before each
// conjugate-gradient iteration of a velocity solve (and once its system is assembled), every
// kNodesBetweenPolls nodes of a distance sweep and once the inside is known (interrupt.h),
// on the thread that called ComputeMap.
using Progress = std::function<bool(double, const std::string &)>;

// samples: extra points on the source (or off it: each follows its own level set) to map
// with the integral formula (Eq. 7) beside the vertices; their images, on the target's
// frame and not projected onto it, go to Result::sampleImages.
void ComputeMap(const Mesh &source, const Mesh &target, const std::vector<AnchorPair> &anchors, const Options &options,
                Result &result, const Progress &progress = {}, const std::vector<Point3> &samples = {});

} // namespace eulermap
