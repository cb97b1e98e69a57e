// The fuzz entries replayed in every build: the seed corpus (the shipped scenes, the seed tables),
// every input a fuzzer once crashed on (tests/fuzz/regressions/<target>/: add the file libFuzzer
// writes, named for what it found), and hand-made hostile inputs. Each must be read or refused with
// an mfwave error; a crash, a sanitizer report or another exception fails the test.

#include "FuzzEntries.hpp"
#include "core/BoundedRead.hpp"
#include "io/checkpoint/Checkpoint.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace mfwave::fuzz {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> filesUnder(const fs::path& folder, const std::string& extension = "") {
  std::vector<fs::path> files;
  if (!fs::exists(folder)) return files;
  for (const auto& entry : fs::directory_iterator(folder))
    if (entry.is_regular_file() && (extension.empty() || entry.path().extension() == extension))
      files.push_back(entry.path());
  return files;
}

std::string bytesOf(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void readScene(const std::string& bytes) {
  readSceneBytes(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

void readCheckpoint(const std::string& bytes) {
  readCheckpointBytes(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

void readTable(const std::string& bytes) {
  readTimeFunctionBytes(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

const fs::path kSource = MFWAVE_SOURCE_DIR;

TEST(FuzzReplay, ShippedScenesAndSceneRegressions) {
  std::vector<fs::path> inputs = filesUnder(kSource / "data" / "scenes", ".toml");
  ASSERT_GE(inputs.size(), 10u);
  for (const fs::path& p : filesUnder(kSource / "tests" / "fuzz" / "regressions" / "scene")) inputs.push_back(p);
  for (const fs::path& p : inputs) EXPECT_NO_THROW(readScene(bytesOf(p))) << p;
}

TEST(FuzzReplay, SeedTablesAndTableRegressions) {
  std::vector<fs::path> inputs = filesUnder(kSource / "tests" / "fuzz" / "seeds" / "time_function");
  ASSERT_GE(inputs.size(), 2u);
  for (const fs::path& p : filesUnder(kSource / "tests" / "fuzz" / "regressions" / "time_function")) inputs.push_back(p);
  for (const fs::path& p : inputs) EXPECT_NO_THROW(readTable(bytesOf(p))) << p;
}

TEST(FuzzReplay, HandMadeHostileScenes) {
  std::string deepKey = "a";
  for (int i = 0; i < 200000; ++i) deepKey += ".a";
  const std::vector<std::string> inputs = {
      "",
      std::string("\0", 1),
      std::string("[scene]\nname = \"x\"\0geometry.spacing=\n=\n\0\0", 40),
      deepKey + " = 1",
      "a = " + std::string(100000, '[') + std::string(100000, ']'),
      "[geometry]\nspacing = 1e-300\nlower = [0, 0]\nupper = [1e300, 1e300]\n",
      "[[probe]]\n[[probe]]\nparticle = -9223372036854775808\n",
      std::string(kMaxSceneBytes + 1, '#'),  // over the text limit
  };
  for (const std::string& input : inputs) EXPECT_NO_THROW(readScene(input)) << input.substr(0, 80);
}

TEST(FuzzReplay, HandMadeHostileTables) {
  const std::vector<std::string> inputs = {"", "t,v\n", "0,0\n0,1\n", "0,nan\n1,1\n", "0,0\n1e308,1\n-1e308,2\n",
                                           "0 0 0\n", "header\nheader2\n0,0\n1,1\n", std::string(1000, ',')};
  for (const std::string& input : inputs) EXPECT_NO_THROW(readTable(input)) << input.substr(0, 80);
}

TEST(FuzzReplay, SeedCheckpointsAndCheckpointRegressions) {
  std::vector<fs::path> inputs = filesUnder(kSource / "tests" / "fuzz" / "seeds" / "checkpoint");
  ASSERT_GE(inputs.size(), 2u);
  // the seed file is a whole checkpoint (written by hand to the layout of Checkpoint.hpp)
  const Checkpoint seed = decodeCheckpoint(bytesOf(kSource / "tests" / "fuzz" / "seeds" / "checkpoint" / "two-arrays.mfwc"), "seed");
  EXPECT_EQ(seed.step, 12);
  EXPECT_EQ(seed.array("displacement"), (std::vector<Real>{1.0, -2.5, 1e-300}));
  for (const fs::path& p : filesUnder(kSource / "tests" / "fuzz" / "regressions" / "checkpoint")) inputs.push_back(p);
  for (const fs::path& p : inputs) EXPECT_NO_THROW(readCheckpoint(bytesOf(p))) << p;
  // hand-made payloads: an array count and an array length far beyond the bytes, a string length of 2^63
  std::string huge(8, '\0');
  huge += std::string(8, '\xff');
  EXPECT_NO_THROW(readCheckpoint(huge));
  EXPECT_NO_THROW(readCheckpoint(std::string(40, '\xff')));
  EXPECT_NO_THROW(readCheckpoint(""));
}

}  // namespace
}  // namespace mfwave::fuzz
