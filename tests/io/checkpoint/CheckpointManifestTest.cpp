// lib/io/checkpoint/CheckpointManifest: the manifest of a run on ranks reads back field for field
// (its time to the last bit), a damaged one is refused naming --restart, a folder without one has
// none, and a serial store refuses to restart from a folder that has one.

#include "core/Error.hpp"
#include "io/checkpoint/CheckpointManifest.hpp"
#include "io/checkpoint/FolderCheckpointStore.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace mfwave {
namespace {

namespace fs = std::filesystem;

fs::path manifestFolder(const std::string& name) {
  const fs::path folder = fs::temp_directory_path() / ("mfwave-manifest-" + name);
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

CheckpointManifest sampleManifest() {
  CheckpointManifest m;
  m.ranks = 3;
  m.sceneDigest = "crc32c 0123abcd, 2049 bytes";  // with spaces, as SceneReader writes it
  m.loop = 2;
  m.step = 40;
  m.time = 0.1 + 1e-17;
  m.files = {"rank-0-of-3/checkpoint-0002-000000000040.mfwc", "rank-1-of-3/checkpoint-0002-000000000040.mfwc",
             "rank-2-of-3/checkpoint-0002-000000000040.mfwc"};
  return m;
}

TEST(CheckpointManifest, ReadsBackFieldForField) {
  const fs::path folder = manifestFolder("round-trip");
  EXPECT_FALSE(readCheckpointManifest(folder.string()));
  const CheckpointManifest written = sampleManifest();
  writeCheckpointManifest(folder.string(), written);
  const std::optional<CheckpointManifest> read = readCheckpointManifest(folder.string());
  ASSERT_TRUE(read);
  EXPECT_EQ(read->ranks, 3);
  EXPECT_EQ(read->sceneDigest, written.sceneDigest);
  EXPECT_EQ(read->loop, 2);
  EXPECT_EQ(read->step, 40);
  EXPECT_EQ(read->time, written.time);  // bit for bit
  EXPECT_FALSE(read->rankZeroAlone);
  EXPECT_EQ(read->files, written.files);
  EXPECT_EQ(rankCheckpointFolderName(1, 3), "rank-1-of-3");
  for (const auto& entry : fs::directory_iterator(folder))  // no temporary left behind
    EXPECT_EQ(entry.path().filename(), kCheckpointManifestName);
}

TEST(CheckpointManifest, DamagedOneIsRefusedNamingRestart) {
  const fs::path folder = manifestFolder("damaged");
  for (const std::string text : {"not a manifest\n", "mfwave-checkpoint-manifest 9\nranks 2\nstep 1\n",
                                 "mfwave-checkpoint-manifest 1\nranks two\nstep 1\n",
                                 "mfwave-checkpoint-manifest 1\nstep 1\n"}) {
    std::ofstream(folder / kCheckpointManifestName) << text;
    try {
      (void)readCheckpointManifest(folder.string());
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), "--restart");
    }
  }
}

TEST(CheckpointManifest, SerialRestartFromRankCheckpointsIsRefused) {
  const fs::path folder = manifestFolder("serial");
  writeCheckpointManifest(folder.string(), sampleManifest());
  CheckpointSettings settings;
  settings.everySteps = 10;
  settings.restartFolder = folder.string();
  try {
    FolderCheckpointStore store((manifestFolder("serial-out")).string(), "crc32c 0123abcd, 2049 bytes", settings);
    FAIL() << "a serial restart from checkpoints of 3 ranks was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "--restart");
    EXPECT_NE(std::string(e.what()).find("3 MPI ranks; this run is serial"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mfwave
