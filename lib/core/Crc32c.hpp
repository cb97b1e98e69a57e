#pragma once
// CRC-32C (Castagnoli, the polynomial 0x1EDC6F41, reflected 0x82F63B78), the checksum of iSCSI,
// ext4 and Btrfs metadata: detects every burst error up to 32 bits and every odd number of flipped
// bits, which is what a checkpoint needs to tell a damaged file from a whole one. Byte-wise table
// version (no SSE4.2 dependence, so the value is the same on every machine).

#include <cstddef>
#include <cstdint>

namespace mfwave {

// The CRC-32C of `size` bytes, continuing from `crc` (0 to start): crc32c(b, crc32c(a)) equals the
// CRC of a followed by b. crc32c("123456789") = 0xE3069283.
std::uint32_t crc32c(const void* data, std::size_t size, std::uint32_t crc = 0);

}  // namespace mfwave
