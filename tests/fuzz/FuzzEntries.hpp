#pragma once
// What the fuzz targets feed their bytes through, shared by the libFuzzer programs (built with
// -DMFWAVE_FUZZ=ON and clang, tests/fuzz/CMakeLists.txt) and by FuzzEntriesTest, which replays the
// seed corpus and every input that once crashed (tests/fuzz/regressions/) in every build.
//
// An entry returns normally when the input was read or refused with an mfwave error (InputError,
// SceneError: the clean refusal a user sees as exit 2). Anything else escapes: a crash, a
// sanitizer report, or another exception (std::out_of_range, std::bad_alloc, ...) is a finding.

#include <cstddef>
#include <cstdint>

namespace mfwave::fuzz {

// Scene text: bytes up to the first NUL are the scene file; after it, each line is a --set
// override. Parsed with the common schema (SceneSchema::common), read by readScene, its unknown
// keys checked and the resolved scene written out as drivers do (relative file paths resolve
// against a folder that does not exist).
void readSceneBytes(const std::uint8_t* data, std::size_t size);

// A time-function CSV table (TimeFunction::fromCsvText), evaluated at its breakpoints and between.
void readTimeFunctionBytes(const std::uint8_t* data, std::size_t size);

// A checkpoint file (decodeCheckpoint), and the same bytes as the payload of a checkpoint whose
// header and CRC-32C are made to fit, so that the payload's reader is reached past the checksum.
// A clean refusal here is CorruptCheckpoint or InputError.
void readCheckpointBytes(const std::uint8_t* data, std::size_t size);

}  // namespace mfwave::fuzz
