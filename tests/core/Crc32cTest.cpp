// lib/core/Crc32c: the published check value, continuation, and that every single flipped bit of a
// block changes it.

#include "core/Crc32c.hpp"

#include <gtest/gtest.h>

#include <string>

namespace mfwave {
namespace {

TEST(Crc32c, CheckValueContinuationAndSingleBitFlips) {
  const std::string digits = "123456789";
  EXPECT_EQ(crc32c(digits.data(), digits.size()), 0xE3069283u);  // the CRC-32C check value (RFC 3720)
  EXPECT_EQ(crc32c(nullptr, 0), 0u);
  EXPECT_EQ(crc32c(digits.data() + 4, 5, crc32c(digits.data(), 4)), 0xE3069283u);
  std::string block(256, '\0');
  for (std::size_t i = 0; i < block.size(); ++i) block[i] = static_cast<char>(i * 7 + 3);
  const std::uint32_t whole = crc32c(block.data(), block.size());
  for (std::size_t bit = 0; bit < 8 * block.size(); ++bit) {
    std::string flipped = block;
    flipped[bit / 8] = static_cast<char>(flipped[bit / 8] ^ (1 << (bit % 8)));
    ASSERT_NE(crc32c(flipped.data(), flipped.size()), whole) << "bit " << bit;
  }
}

}  // namespace
}  // namespace mfwave
