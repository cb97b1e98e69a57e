#pragma once
// A checkpoint: what a run needs to go on from a step as if it had never stopped (issue 20). This
// file is the container and its checks; what goes into it (state arrays, the integrator's history,
// observers' buffers) is the run's business, by name.
//
// Binary layout, version 1 (the host's byte order, recorded and checked):
//   "MFWCKPT\0" (8 bytes) | u32 format version | u32 byte-order mark 0x01020304 | u64 payload bytes |
//   payload | u32 CRC-32C of the payload (core/Crc32c)
//   payload: str scene digest | i64 step | f64 time | u64 array count | per array: str name, u64 n, n f64
//   str: u64 length, then the bytes
// Every length is checked against the bytes left before anything is allocated, so a damaged or
// hostile file is refused and never makes the reader allocate what the file does not hold.

#include "core/Error.hpp"
#include "core/Types.hpp"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace mfwave {

inline constexpr std::uint32_t kCheckpointFormatVersion = 1;

// A file that is not a whole checkpoint: truncated, a flipped byte (the checksum), not a checkpoint
// at all. A restart skips it and tries the one before.
class CorruptCheckpoint : public Error {
 public:
  using Error::Error;
};

struct Checkpoint {
  std::string sceneDigest;  // identifies the resolved scene: a checkpoint of another scene is refused
  std::int64_t step = 0;
  Real time = 0;
  std::vector<std::pair<std::string, std::vector<Real>>> arrays;  // in the order added

  void add(std::string name, std::vector<Real> values);
  // Throws InputError("checkpoint", ...) naming the array when there is none of that name.
  const std::vector<Real>& array(const std::string& name) const;
};

// The file's bytes.
std::string encodeCheckpoint(const Checkpoint& checkpoint);

// The checkpoint held by `bytes` (`source` names it in messages). Throws CorruptCheckpoint when the
// bytes are not a whole checkpoint, InputError("--restart", ...) when they are one of another format
// version or byte order (a whole file this build cannot read).
Checkpoint decodeCheckpoint(const std::string& bytes, const std::string& source);

}  // namespace mfwave
