#include "core/AtomicFile.hpp"
#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace mfwave;
namespace fs = std::filesystem;

namespace {
fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("mfwave-test-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}
std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

TEST(AtomicFile, FileAppearsOnlyOnCommit) {
  const fs::path path = scratch("a.csv");
  fs::remove(path);
  {
    AtomicFile file(path.string());
    file.stream() << "t,u\n0,1\n";
    EXPECT_FALSE(fs::exists(path));
    file.commit();
  }
  EXPECT_EQ(slurp(path), "t,u\n0,1\n");
}

TEST(AtomicFile, AbandonedWriteLeavesTheOldFileAndNoTemporary) {
  const fs::path path = scratch("b.csv");
  {
    std::ofstream old(path);
    old << "old\n";
  }
  {
    AtomicFile file(path.string());
    file.stream() << "half a fil";
  }  // destroyed without commit, as when an exception unwinds a run
  EXPECT_EQ(slurp(path), "old\n");
  for (const auto& entry : fs::directory_iterator(path.parent_path()))
    EXPECT_EQ(entry.path().string().find(".tmp-"), std::string::npos) << entry.path();
}

TEST(AtomicFile, UnwritableDirectoryIsAClearError) {
  try {
    AtomicFile file("/nonexistent-dir-mfwave/x.csv");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir-mfwave/x.csv"), std::string::npos);
  }
}
