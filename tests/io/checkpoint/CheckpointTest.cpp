// lib/io/checkpoint: a checkpoint reads back bit for bit; a flipped byte anywhere and a truncation
// anywhere are detected; a restart takes the newest whole checkpoint, skipping damaged ones with a
// message naming them; another scene's or another format version's checkpoint is refused; only the
// newest two are kept.

#include "core/Error.hpp"
#include "io/checkpoint/Checkpoint.hpp"
#include "io/checkpoint/CheckpointFolder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

namespace mfwave {
namespace {

namespace fs = std::filesystem;

Checkpoint sample(std::int64_t step) {
  Checkpoint c;
  c.sceneDigest = "scene-a";
  c.step = step;
  c.time = 0.1 * static_cast<Real>(step) + 1e-17;
  std::vector<Real> u(1000);
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = std::sin(0.37 * static_cast<Real>(i)) * 1e-3;
  u[7] = std::numeric_limits<Real>::denorm_min();
  u[8] = -0.0;
  c.add("displacement", u);
  c.add("half_step_velocity", std::vector<Real>(1000, 0.25));
  c.add("empty", {});
  return c;
}

fs::path freshFolder(const std::string& name) {
  const fs::path folder = fs::temp_directory_path() / ("mfwave-checkpoint-" + name);
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

std::string bytesOf(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void writeBytes(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

TEST(Checkpoint, ReadsBackBitForBit) {
  const Checkpoint c = sample(42);
  const Checkpoint back = decodeCheckpoint(encodeCheckpoint(c), "memory");
  EXPECT_EQ(back.sceneDigest, "scene-a");
  EXPECT_EQ(back.step, 42);
  EXPECT_EQ(std::memcmp(&back.time, &c.time, sizeof(Real)), 0);
  ASSERT_EQ(back.arrays.size(), 3u);
  for (std::size_t a = 0; a < 3; ++a) {
    EXPECT_EQ(back.arrays[a].first, c.arrays[a].first);
    ASSERT_EQ(back.arrays[a].second.size(), c.arrays[a].second.size());
    if (!c.arrays[a].second.empty()) {
      EXPECT_EQ(std::memcmp(back.arrays[a].second.data(), c.arrays[a].second.data(),
                            c.arrays[a].second.size() * sizeof(Real)),
                0);
    }
  }
  EXPECT_TRUE(std::signbit(back.array("displacement")[8]));
  EXPECT_THROW(back.array("velocity"), InputError);
}

TEST(Checkpoint, EveryFlippedByteAndEveryTruncationIsDetected) {
  Checkpoint c;
  c.sceneDigest = "s";
  c.step = 3;
  c.add("u", {1.0, 2.0, 3.0});
  const std::string bytes = encodeCheckpoint(c);
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    std::string damaged = bytes;
    damaged[i] = static_cast<char>(damaged[i] ^ 0x10);
    // the version field (bytes 8-11) flipped reads as a whole file of another version: refused, not skipped
    if (i >= 8 && i < 12) {
      EXPECT_THROW(decodeCheckpoint(damaged, "x"), InputError) << "byte " << i;
      continue;
    }
    EXPECT_THROW(decodeCheckpoint(damaged, "x"), CorruptCheckpoint) << "byte " << i;
  }
  for (std::size_t n = 0; n < bytes.size(); ++n)
    EXPECT_THROW(decodeCheckpoint(bytes.substr(0, n), "x"), CorruptCheckpoint) << n << " bytes";
  EXPECT_THROW(decodeCheckpoint(bytes + "x", "x"), CorruptCheckpoint);
}

TEST(CheckpointFolder, KeepsTheNewestTwoAndRestartsFromTheNewestWholeOne) {
  const fs::path folder = freshFolder("keep");
  for (std::int64_t step : {10, 20, 30}) writeCheckpoint(folder.string(), sample(step));
  const std::vector<std::string> files = checkpointFiles(folder.string());
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(fs::path(files[0]).filename(), "checkpoint-0000-000000000030.mfwc");
  EXPECT_EQ(fs::path(files[1]).filename(), "checkpoint-0000-000000000020.mfwc");
  for (const auto& entry : fs::directory_iterator(folder))  // no temporary left behind
    EXPECT_EQ(entry.path().extension(), ".mfwc") << entry.path();

  RestartPoint point = readNewestCheckpoint(folder.string(), "scene-a");
  EXPECT_EQ(point.checkpoint.step, 30);
  EXPECT_TRUE(point.skipped.empty());

  // The newest damaged by one byte: skipped with a message naming it, the one before taken.
  std::string bytes = bytesOf(files[0]);
  bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 1);
  writeBytes(files[0], bytes);
  point = readNewestCheckpoint(folder.string(), "scene-a");
  EXPECT_EQ(point.checkpoint.step, 20);
  ASSERT_EQ(point.skipped.size(), 1u);
  EXPECT_NE(point.skipped[0].find("checkpoint-0000-000000000030.mfwc"), std::string::npos) << point.skipped[0];
  EXPECT_NE(point.skipped[0].find("CRC-32C"), std::string::npos) << point.skipped[0];

  // Both damaged (the older one truncated): none to restart from, both named.
  const std::string older = bytesOf(files[1]);
  writeBytes(files[1], older.substr(0, older.size() - 9));
  try {
    readNewestCheckpoint(folder.string(), "scene-a");
    FAIL() << "a folder of damaged checkpoints was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "--restart");
    EXPECT_NE(std::string(e.what()).find("no whole checkpoint"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
  }
  fs::remove_all(folder);
}

TEST(CheckpointFolder, AnotherScenesOrVersionsCheckpointIsRefused) {
  const fs::path folder = freshFolder("refuse");
  writeCheckpoint(folder.string(), sample(5));
  EXPECT_THROW(readNewestCheckpoint(folder.string(), "scene-b"), InputError);
  // version 2 of the format, written whole
  std::string bytes = bytesOf(checkpointFiles(folder.string())[0]);
  const std::uint32_t version = 2;
  std::memcpy(&bytes[8], &version, sizeof(version));
  writeBytes(checkpointFiles(folder.string())[0], bytes);
  try {
    readNewestCheckpoint(folder.string(), "scene-a");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("format version 2"), std::string::npos) << e.what();
  }
  EXPECT_THROW(readNewestCheckpoint((folder / "missing").string(), "scene-a"), InputError);
  fs::remove_all(folder);
}

}  // namespace
}  // namespace mfwave
