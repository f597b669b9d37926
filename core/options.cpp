#include "options.h"

#include "parameters.h"

namespace eulermap {

void Options::Validate() const {
  if (gridNodes != vcg::Point3i(0, 0, 0) && (gridNodes.X() < 2 || gridNodes.Y() < 2 || gridNodes.Z() < 2))
    throw Error("grid nodes: give at least 2 nodes on every axis");
  for (const Parameter &p : Parameters())
    if (gridNodes == vcg::Point3i(0, 0, 0) || p.name != std::string("grid_resolution")) p.Check(*this);
}

} // namespace eulermap
