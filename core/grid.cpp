#include "grid.h"

#include <algorithm>
#include <cmath>

namespace eulermap {

Grid Grid::Enclosing(const Box3 &box, int cellsOnLongestAxis, double padCells) {
  Grid g;
  const Point3 size = box.Dim();
  const double longest = std::max({size.X(), size.Y(), size.Z()});
  g.h = longest / std::max(1.0, cellsOnLongestAxis - 2 * padCells);
  for (int a = 0; a < 3; ++a) g.dims[a] = int(std::ceil(size[a] / g.h + 2 * padCells)) + 1;
  const Point3 span = Point3(g.dims.X() - 1, g.dims.Y() - 1, g.dims.Z() - 1) * g.h;
  g.origin = box.Center() - span / 2;
  return g;
}

Grid Grid::WithNodes(const Box3 &box, vcg::Point3i nodes, double padCells) {
  Grid g;
  g.dims = nodes;
  g.h = 0;
  for (int a = 0; a < 3; ++a) g.h = std::max(g.h, box.Dim()[a] / std::max(1.0, nodes[a] - 1 - 2 * padCells));
  const Point3 span = Point3(nodes.X() - 1, nodes.Y() - 1, nodes.Z() - 1) * g.h;
  g.origin = box.Center() - span / 2;
  return g;
}

} // namespace eulermap
