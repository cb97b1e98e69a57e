// A case is refused before allocating when its estimate exceeds the machine's memory, with the
// figures that make the estimate (io/run/MemoryGuard).

#include "io/run/MemoryGuard.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <string>

namespace mfwave {
namespace {

TEST(MemoryGuard, RefusesOnlyWhatExceedsTheMachineAndSaysWhy) {
  const MemoryEstimate estimate{1e6, 3072, "the UL-SPH in 2-D, 1.4 KiB measured"};
  EXPECT_NEAR(estimate.mib(), 2929.7, 0.1);
  EXPECT_TRUE(memoryRefusal("case a", estimate, 4096).empty());
  const std::string why = memoryRefusal("case a", estimate, 2048);
  EXPECT_EQ(why, "case a needs about 2.86 GiB (1000000 particles at about 3072 bytes each: the UL-SPH in 2-D, 1.4 KiB "
                 "measured); this machine has 2 GiB");
  // A machine whose memory cannot be read refuses nothing (the allocation itself then decides).
  EXPECT_TRUE(memoryRefusal("case a", estimate, std::numeric_limits<double>::quiet_NaN()).empty());
}

}  // namespace
}  // namespace mfwave
