#pragma once
// Reading a whole input file into memory, never more than a stated limit: a scene or a table that
// names /dev/zero, a multi-gigabyte file or a /proc file (whose reported size is 0) is refused
// after limit + 1 bytes instead of exhausting the memory. The limits are documented in
// docs/reliability.md ("Limits").

#include <cstddef>
#include <string>

namespace mfwave {

inline constexpr std::size_t kMaxSceneBytes = std::size_t(4) << 20;   // a scene file (shipped ones: < 10 KiB)
inline constexpr std::size_t kMaxTableBytes = std::size_t(64) << 20;  // a time-function CSV (~3 million rows)

// The file's bytes. Throws InputError(key, "cannot read <what> '<path>': ...") when it is not a
// regular file, cannot be read, or holds more than maxBytes ("larger than the limit of N bytes").
std::string readBoundedFile(const std::string& path, std::size_t maxBytes, const std::string& key,
                            const std::string& what);

}  // namespace mfwave
