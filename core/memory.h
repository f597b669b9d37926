// eulermap memory budget: what this process may still allocate, and what a grid costs,
// so that a grid too large is refused before anything is allocated (a filter that runs
// out of memory takes the whole MeshLab session, unsaved work and all, down with it).
#pragma once

#include <cstddef>

namespace eulermap {

// Peak bytes per grid node of a whole run: the fields f0, f1 (8 + 8), the frames f(., t_k)
// and f(., t_k+1) (8 + 8), V_k (24), the gradients of the last pull-back (12), the solver's
// single-precision vectors (g, shift, x, r, p, q, V_k-2: 76, ghosts around the grid
// included) and its multigrid levels (the coarse ones: about 15); with anchors, their
// motion and weights (24 + 8). Measured peak over nodes without anchors (eulermap_bench
// grid 256: 2752 MiB peak RSS for 256^3 nodes, the meshes included) is 172 B (grid 384:
// 9123 MiB, 169 B); the anchors' 32 B lie within RunBytes' margin.
constexpr std::size_t kBytesPerGridNode = 180;
// Bytes per tracked point (position, level, trajectory state, surgery's records).
constexpr std::size_t kBytesPerPoint = 400;

// out: the bytes this process may still allocate: the least of the system's available
//      memory (/proc/meminfo MemAvailable), the cgroup's limit less its use (v2 and v1),
//      and the address-space limit (RLIMIT_AS) less the address space in use. Reads only
//      what Linux offers; elsewhere a large number.
std::size_t AvailableBytes();

// in:  grid nodes and tracked points of a run
// out: the bytes the run needs at its peak, with a margin of 25%
std::size_t RunBytes(std::size_t gridNodes, std::size_t points);

} // namespace eulermap
