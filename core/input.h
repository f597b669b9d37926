// eulermap::PrepareMesh, CheckAnchors — what a host hands to the pipeline, checked in one
// place for every host (MeshLab 2020.09, pymeshlab, the tests), and repaired on the
// pipeline's private copy where that is safe. Nothing here crashes on what a file or an
// array can hold: NaN, Inf, faces that repeat a vertex, faces of zero area, vertices no face
// uses, triangle soups, meshes turned inside out.
#pragma once

#include "options.h"

#include <string>
#include <vector>

namespace eulermap {

// in:  mesh — the pipeline's private copy (changed in place; vertex and face order kept
//      when nothing is repaired); role — "source" or "target", for the messages
// out: mesh repaired, in this order, each step said in `notes` when it changed something:
//        1. faces that repeat a vertex index removed ("3 0 0 1": no area, no normal);
//        2. vertices no face uses removed (a stray point would stretch the grid);
//        3. refused (Error) if a vertex left has a NaN or Inf coordinate, or the mesh has
//           no faces or no extent;
//        4. welded: vertices at exactly the same position with the same texture coordinate
//           and colour merged into one (triangle soups, as STL files store meshes: every
//           face its own three vertices), and faces made twice by that removed;
//        5. faces of zero area (their height below 1e-6 of the bounding-box diagonal:
//           collinear corners, up to single-precision rounding) mended where the surface
//           closes round them, so that it stays closed (corners at one place welded, the
//           edge a corner lies on flipped), removed elsewhere with the vertices only they
//           used; refused if none is left;
//        6. oriented: within each part, faces turned to agree with their neighbours across
//           manifold edges; then each connected part whose signed volume is negative (faces
//           pointing inward) turned outward, as the signed distance's inside needs.
//      The mesh is compact (no deleted vertices or faces) with an up-to-date bounding box.
void PrepareMesh(Mesh &mesh, const std::string &role, std::vector<std::string> &notes);

// in:  anchor pairs as a host gives them
// out: throws Error naming the anchor when a coordinate is NaN or Inf, or when two anchors
//      of one mesh coincide (their interpolation needs distinct points)
void CheckAnchors(const std::vector<AnchorPair> &anchors);

} // namespace eulermap
