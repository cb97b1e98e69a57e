#include "FuzzEntries.hpp"

#include "core/Error.hpp"
#include "core/Crc32c.hpp"
#include "core/TimeFunction.hpp"
#include "io/checkpoint/Checkpoint.hpp"
#include "io/scene/LoadScene.hpp"
#include "io/scene/Scene.hpp"

#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

namespace mfwave::fuzz {

void readSceneBytes(const std::uint8_t* data, std::size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> overrides;
  const std::size_t nul = text.find('\0');
  if (nul != std::string::npos) {
    std::istringstream lines(text.substr(nul + 1));
    for (std::string line; std::getline(lines, line);) overrides.push_back(line);
    text.resize(nul);
  }
  try {
    SceneReader reader = parseScene(text, "fuzz.toml", overrides, SceneSchema::common(), "/nonexistent-mfwave-fuzz");
    const Scene scene = readScene(reader);
    reader.checkAllKeysRead();
    const std::string resolved = reader.resolvedToml();
    (void)scene;
    (void)resolved;
  } catch (const InputError&) {
    // a clean refusal
  }
}

void readTimeFunctionBytes(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const TimeFunction f = TimeFunction::fromCsvText(text, "fuzz.csv");
    std::vector<Real> times, values;
    if (f.piecewiseLinear(times, values)) {
      volatile Real sum = f.quietAfter();
      for (std::size_t i = 0; i < times.size(); ++i) {
        sum = sum + f(times[i]);
        if (i + 1 < times.size()) sum = sum + f(0.5 * (times[i] + times[i + 1]));
      }
    }
  } catch (const InputError&) {
  }
}

void readCheckpointBytes(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  try {
    (void)decodeCheckpoint(bytes, "fuzz.mfwc");
  } catch (const CorruptCheckpoint&) {
  } catch (const InputError&) {
  }
  // The same bytes as a payload behind a fitting header and checksum (the layout of Checkpoint.hpp).
  std::string framed = "MFWCKPT";
  framed.push_back('\0');
  const std::uint32_t version = kCheckpointFormatVersion, mark = 0x01020304u;
  const std::uint64_t length = bytes.size();
  const std::uint32_t crc = crc32c(bytes.data(), bytes.size());
  framed.append(reinterpret_cast<const char*>(&version), sizeof(version));
  framed.append(reinterpret_cast<const char*>(&mark), sizeof(mark));
  framed.append(reinterpret_cast<const char*>(&length), sizeof(length));
  framed += bytes;
  framed.append(reinterpret_cast<const char*>(&crc), sizeof(crc));
  try {
    const Checkpoint c = decodeCheckpoint(framed, "fuzz-framed.mfwc");
    if (encodeCheckpoint(c) != framed) std::abort();  // what reads whole must write back the same bytes
  } catch (const CorruptCheckpoint&) {
  } catch (const InputError&) {
  }
}

}  // namespace mfwave::fuzz
