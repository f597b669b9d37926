// The memory budget (memory.h): what the process may still allocate follows its address-space
// limit; what a run needs grows in proportion to its grid and its points; and a grid that
// does not fit is refused before anything large is allocated, with a message that names the
// grid, what the run needs and what the process may have.
#include "core/grid.h"
#include "core/memory.h"
#include "core/pipeline.h"
#include "tests/support/meshes.h"

#include <sys/resource.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <regex>
#include <string>

using namespace eulermap;
using namespace eulermap::testing;

namespace {

constexpr std::size_t kMiB = std::size_t(1) << 20, kGiB = std::size_t(1) << 30;

// A "Key: N kB" line of /proc/self/status, in bytes (0 when absent).
std::size_t StatusBytes(const std::string &key) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind(key + ":", 0) == 0) return std::size_t(std::stoull(line.substr(key.size() + 1))) * 1024;
  return 0;
}

// Sets RLIMIT_AS to the address space in use plus `more` (a fixed limit would leave
// AddressSanitizer, whose shadow memory alone takes terabytes of it, none to map) and puts
// the old limit back when it goes.
class AddressSpaceLimit {
 public:
  explicit AddressSpaceLimit(std::size_t more) {
    getrlimit(RLIMIT_AS, &saved_);
    rlimit tight = saved_;
    tight.rlim_cur = StatusBytes("VmSize") + more;
    set_ = StatusBytes("VmSize") > 0 && setrlimit(RLIMIT_AS, &tight) == 0;
  }
  ~AddressSpaceLimit() { setrlimit(RLIMIT_AS, &saved_); }
  bool Set() const { return set_; }

 private:
  rlimit saved_{};
  bool set_ = false;
};

TEST(Memory, TheRoomLeftFollowsTheAddressSpaceLimit) {
  const std::size_t unlimited = AvailableBytes();
  std::size_t limited = 0;
  {
    AddressSpaceLimit limit(kGiB);
    ASSERT_TRUE(limit.Set());
    limited = AvailableBytes();
  }
  EXPECT_LE(limited, kGiB);
  if (unlimited > 2 * kGiB) {  // a machine with room: the limit decides, and goes with it
    EXPECT_GT(limited, kGiB / 2);  // the little this test maps in between
    EXPECT_GT(AvailableBytes(), kGiB + kGiB / 2);
  }
}

TEST(Memory, ARunNeedsInProportionToItsGridAndPoints) {
  const std::size_t n = std::size_t(64) * 64 * 64, points = 100000;
  EXPECT_EQ(RunBytes(0, 0), 0u);
  EXPECT_NEAR(double(RunBytes(8 * n, 0)), 8.0 * RunBytes(n, 0), 8.0);  // integer rounding only
  EXPECT_NEAR(double(RunBytes(0, 4 * points)), 4.0 * RunBytes(0, points), 8.0);
  EXPECT_NEAR(double(RunBytes(n, points)), double(RunBytes(n, 0)) + RunBytes(0, points), 8.0);
  // At least f0, f1 and one velocity field in single precision per node, and a position
  // per point; a 256^3 grid fits in 16 GiB.
  EXPECT_GE(RunBytes(n, 0), n * (2 + 3) * sizeof(float));
  EXPECT_GE(RunBytes(0, points), points * 3 * sizeof(double));
  EXPECT_LT(RunBytes(std::size_t(256) * 256 * 256, 0), 16 * kGiB);
}

// Under a limit of 2 GiB more than in use, grid_resolution 400 (about 400^3 nodes) is
// refused: the message names the node count, the MiB the run needs and the MiB the process
// may have, and the process's peak resident memory has not grown by a grid's worth.
TEST(Memory, AGridThatDoesNotFitIsRefusedBeforeAllocating) {
  Mesh source, target;
  MakeSphere(source, Point3(0, 0, 0), 1, 2);
  MakeSphere(target, Point3(0, 0, 0), 1.2, 2);
  Options o;
  o.gridResolution = 400;
  std::string message;
  std::size_t room = 0, peakBefore = 0, peakAfter = 0;
  {
    AddressSpaceLimit limit(2 * kGiB);
    ASSERT_TRUE(limit.Set());
    room = AvailableBytes();
    peakBefore = StatusBytes("VmHWM");
    Result result;
    try {
      ComputeMap(source, target, {}, o, result);
    } catch (const Error &e) {
      message = e.what();
    }
    peakAfter = StatusBytes("VmHWM");
  }
  std::smatch m;
  ASSERT_TRUE(std::regex_search(message, m,
                                std::regex("^grid_resolution 400: the grid would have ([0-9]+) nodes and the run about "
                                           "([0-9]+) MiB, but this process may have only ([0-9]+) MiB more: lower "
                                           "grid_resolution")))
      << message;
  const std::size_t nodes = std::stoull(m[1]), need = std::stoull(m[2]) * kMiB, have = std::stoull(m[3]) * kMiB;
  // Centre-and-scale puts the target on the source: the grid is about the source's.
  EXPECT_NEAR(double(nodes), double(Grid::Enclosing(source.bbox, 400).NodeCount()), 0.02 * nodes);
  EXPECT_GE(need + kMiB, RunBytes(nodes, 0));
  EXPECT_GT(need, have);
  EXPECT_LT(std::max(have, room) - std::min(have, room), 256 * kMiB) << "the room the refusal names is not the room left";
  EXPECT_LT(peakAfter - peakBefore, 256 * kMiB) << "allocated before refusing";
}

} // namespace
