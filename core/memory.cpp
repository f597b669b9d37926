#include "memory.h"

#include <sys/resource.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <string>

namespace eulermap {

namespace {

constexpr std::size_t kUnknown = std::numeric_limits<std::size_t>::max();

// The first number in `file`, kUnknown when unreadable or "max".
std::size_t ReadNumber(const std::string &file) {
  std::ifstream in(file);
  unsigned long long x = 0;
  return in >> x ? std::size_t(x) : kUnknown;
}

// in:  file in /proc's "key: value kB" form, key
// out: the value in bytes, kUnknown when absent
std::size_t ReadKiB(const std::string &file, const std::string &key) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(key + ":", 0) == 0) return std::size_t(std::stoull(line.substr(key.size() + 1))) * 1024;
  return kUnknown;
}

// The cgroup (v2, else v1) this process lives in: limit less use; kUnknown without a limit.
std::size_t CgroupRoom() {
  std::ifstream in("/proc/self/cgroup");
  std::string line;
  while (std::getline(in, line)) {
    const std::size_t colon = line.rfind(':');
    if (colon == std::string::npos) continue;
    const std::string path = line.substr(colon + 1);
    const bool v2 = line.rfind("0::", 0) == 0;
    if (!v2 && line.find(":memory:") == std::string::npos) continue;
    const std::string dir = v2 ? "/sys/fs/cgroup" + path : "/sys/fs/cgroup/memory" + path;
    const std::size_t limit = ReadNumber(dir + (v2 ? "/memory.max" : "/memory.limit_in_bytes"));
    const std::size_t used = ReadNumber(dir + (v2 ? "/memory.current" : "/memory.usage_in_bytes"));
    if (limit == kUnknown || used == kUnknown || limit > (std::size_t(1) << 60)) return kUnknown;
    return limit > used ? limit - used : 0;
  }
  return kUnknown;
}

// RLIMIT_AS less the address space in use; kUnknown without a limit.
std::size_t AddressSpaceRoom() {
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return kUnknown;
  const std::size_t used = ReadKiB("/proc/self/status", "VmSize");
  if (used == kUnknown) return kUnknown;
  return limit.rlim_cur > used ? limit.rlim_cur - used : 0;
}

} // namespace

std::size_t AvailableBytes() {
  return std::min({ReadKiB("/proc/meminfo", "MemAvailable"), CgroupRoom(), AddressSpaceRoom()});
}

std::size_t RunBytes(std::size_t gridNodes, std::size_t points) {
  return (gridNodes * kBytesPerGridNode + points * kBytesPerPoint) / 4 * 5;
}

} // namespace eulermap
