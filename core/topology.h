// Topology of a triangle mesh, as the tests and the report check it after surgery:
// connected components, boundary loops (vcg::tri::Clean::CountHoles) and the Euler
// characteristic chi = V - E + F (unreferenced vertices not counted).
#pragma once

#include "mesh.h"

namespace eulermap {

struct Topology {
  int components = 0;
  int boundaryLoops = 0;
  int eulerCharacteristic = 0;
  // Genus of a connected orientable surface: (2 - chi - loops) / 2.
  int Genus() const { return (2 * components - eulerCharacteristic - boundaryLoops) / 2; }
};

// Updates m's face-face topology.
Topology MeasureTopology(Mesh &m);

// The topology of the surface m describes: as MeasureTopology on a copy whose vertices at
// one place (within kSamePlace of its diagonal) are one. A seam of per-vertex texture
// coordinates or normals splits a closed torus into a square with one boundary loop; its
// surface is still a torus.
constexpr double kSamePlace = 1e-9;
Topology MeasureSurfaceTopology(const Mesh &m);

// The cut source a continuous map needs (DESIGN.md: expected topology after surgery), from
// the source's own topology and the changes of the inside set's components and handles
// from f(., 0) to f(., 1) (zero_set_topology.h). Each handle gained costs two discs (two
// loops, chi - 2), each lost a band around it (two loops, chi kept), each merge of two parts
// a disc on each (two loops, chi - 2), each split a band around the neck (one more
// component, two loops, chi kept): sphere -> genus g: genus 0 with 2g loops; genus g ->
// sphere: genus 0 with 2g loops; two spheres -> one: two discs.
Topology NeededCut(const Topology &source, int componentChange, int handleChange);

} // namespace eulermap
