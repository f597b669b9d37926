#include "topology.h"

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/append.h>

#include <algorithm>
#include <cstdlib>

namespace eulermap {

Topology MeasureTopology(Mesh &m) {
  vcg::tri::UpdateTopology<Mesh>::FaceFace(m);
  Topology t;
  t.components = vcg::tri::Clean<Mesh>::CountConnectedComponents(m);
  t.boundaryLoops = vcg::tri::Clean<Mesh>::CountHoles(m);
  int edges = 0, boundaryEdges = 0, nonManifoldEdges = 0;
  vcg::tri::Clean<Mesh>::CountEdgeNum(m, edges, boundaryEdges, nonManifoldEdges);
  std::vector<bool> used(m.vert.size(), false);
  int faces = 0;
  for (const Face &f : m.face)
    if (!f.IsD()) {
      ++faces;
      for (int c = 0; c < 3; ++c) used[vcg::tri::Index(m, f.cV(c))] = true;
    }
  const int vertices = int(std::count(used.begin(), used.end(), true));
  t.eulerCharacteristic = vertices - edges + faces;
  return t;
}

Topology MeasureSurfaceTopology(const Mesh &m) {
  Mesh surface;
  // vcglib 2020.09's Append takes the mesh it reads as non-const; it only reads it.
  vcg::tri::Append<Mesh, Mesh>::MeshCopy(surface, const_cast<Mesh &>(m), false, false);
  vcg::tri::UpdateBounding<Mesh>::Box(surface);
  vcg::tri::Clean<Mesh>::MergeCloseVertex(surface, kSamePlace * surface.bbox.Diag());  // sin(2 pi) is not 0
  vcg::tri::Allocator<Mesh>::CompactEveryVector(surface);
  return MeasureTopology(surface);
}

Topology NeededCut(const Topology &source, int componentChange, int handleChange) {
  Topology t = source;
  t.components += std::max(0, componentChange);
  t.boundaryLoops += 2 * std::abs(handleChange) + 2 * std::abs(componentChange);
  t.eulerCharacteristic -= 2 * std::max(0, handleChange) + 2 * std::max(0, -componentChange);
  return t;
}

} // namespace eulermap
