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

} // namespace eulermap
