#include "io/checkpoint/Checkpoint.hpp"

#include "core/Crc32c.hpp"

#include <cstring>

namespace mfwave {
namespace {

constexpr char kMagic[8] = {'M', 'F', 'W', 'C', 'K', 'P', 'T', '\0'};
constexpr std::uint32_t kByteOrderMark = 0x01020304u;

template <class T>
void put(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

void putString(std::string& out, const std::string& s) {
  put<std::uint64_t>(out, s.size());
  out += s;
}

// Reads from a byte range, refusing to go past its end.
class Reader {
 public:
  Reader(const char* data, std::size_t size, const std::string& source) : data_(data), size_(size), source_(source) {}

  template <class T>
  T get(const char* what) {
    need(sizeof(T), what);
    T value;
    std::memcpy(&value, data_ + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }

  std::string getString(const char* what) {
    const std::uint64_t n = get<std::uint64_t>(what);
    need(n, what);
    std::string s(data_ + at_, static_cast<std::size_t>(n));
    at_ += static_cast<std::size_t>(n);
    return s;
  }

  std::vector<Real> getReals(const char* what) {
    const std::uint64_t n = get<std::uint64_t>(what);
    if (n > (size_ - at_) / sizeof(Real)) fail(what);
    std::vector<Real> values(static_cast<std::size_t>(n));
    if (n > 0) std::memcpy(values.data(), data_ + at_, static_cast<std::size_t>(n) * sizeof(Real));
    at_ += static_cast<std::size_t>(n) * sizeof(Real);
    return values;
  }

  std::size_t left() const { return size_ - at_; }

  [[noreturn]] void fail(const char* what) const {
    throw CorruptCheckpoint("checkpoint '" + source_ + "' is damaged or truncated: its " + what + " runs past the end");
  }

 private:
  void need(std::uint64_t n, const char* what) const {
    if (n > size_ - at_) fail(what);
  }

  const char* data_;
  std::size_t size_, at_ = 0;
  const std::string& source_;
};

}  // namespace

void Checkpoint::add(std::string name, std::vector<Real> values) {
  arrays.emplace_back(std::move(name), std::move(values));
}

const std::vector<Real>& Checkpoint::array(const std::string& name) const {
  for (const auto& [key, values] : arrays)
    if (key == name) return values;
  throw InputError("checkpoint", "has no array '" + name + "'");
}

std::string encodeCheckpoint(const Checkpoint& checkpoint) {
  std::string payload;
  putString(payload, checkpoint.sceneDigest);
  put<std::int64_t>(payload, checkpoint.step);
  put<double>(payload, checkpoint.time);
  put<std::uint64_t>(payload, checkpoint.arrays.size());
  for (const auto& [name, values] : checkpoint.arrays) {
    putString(payload, name);
    put<std::uint64_t>(payload, values.size());
    payload.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(Real));
  }
  std::string out(kMagic, sizeof(kMagic));
  put<std::uint32_t>(out, kCheckpointFormatVersion);
  put<std::uint32_t>(out, kByteOrderMark);
  put<std::uint64_t>(out, payload.size());
  out += payload;
  put<std::uint32_t>(out, crc32c(payload.data(), payload.size()));
  return out;
}

Checkpoint decodeCheckpoint(const std::string& bytes, const std::string& source) {
  Reader header(bytes.data(), bytes.size(), source);
  if (bytes.size() < sizeof(kMagic) || std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0)
    throw CorruptCheckpoint("'" + source + "' is not an mfwave checkpoint (no MFWCKPT header)");
  header.get<std::uint64_t>("magic");
  const auto version = header.get<std::uint32_t>("format version");
  const auto mark = header.get<std::uint32_t>("byte-order mark");
  if (version != kCheckpointFormatVersion)
    throw InputError("--restart", "checkpoint '" + source + "' has format version " + std::to_string(version) +
                                      "; this build reads version " + std::to_string(kCheckpointFormatVersion));
  if (mark == 0x04030201u)
    throw InputError("--restart", "checkpoint '" + source + "' was written on a machine of the other byte order");
  if (mark != kByteOrderMark) throw CorruptCheckpoint("checkpoint '" + source + "' has a damaged header");
  const auto payloadSize = header.get<std::uint64_t>("payload size");
  if (header.left() < sizeof(std::uint32_t) || payloadSize != header.left() - sizeof(std::uint32_t))
    throw CorruptCheckpoint("checkpoint '" + source + "' is truncated or has bytes after its end (" +
                            std::to_string(bytes.size()) + " bytes for a payload of " + std::to_string(payloadSize) + ")");
  const std::size_t payloadStart = bytes.size() - header.left();
  const char* payload = bytes.data() + payloadStart;
  std::uint32_t stored;
  std::memcpy(&stored, payload + payloadSize, sizeof(stored));
  if (crc32c(payload, static_cast<std::size_t>(payloadSize)) != stored)
    throw CorruptCheckpoint("checkpoint '" + source + "' fails its CRC-32C checksum (a damaged byte)");

  Reader r(payload, static_cast<std::size_t>(payloadSize), source);
  Checkpoint c;
  c.sceneDigest = r.getString("scene digest");
  c.step = r.get<std::int64_t>("step");
  c.time = r.get<double>("time");
  const auto count = r.get<std::uint64_t>("array count");
  for (std::uint64_t i = 0; i < count; ++i) {
    std::string name = r.getString("array name");
    c.add(std::move(name), r.getReals("array"));
  }
  if (r.left() != 0) r.fail("payload");
  return c;
}

}  // namespace mfwave
