// lib/core/BoundedRead: a whole file read, never more than its limit; what cannot be read is refused
// naming the key, what was being read and the path.

#include "core/BoundedRead.hpp"
#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace mfwave {
namespace {

namespace fs = std::filesystem;

std::string refusal(const std::string& path, std::size_t limit) {
  try {
    readBoundedFile(path, limit, "file", "the table");
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "file");
    return e.problem();
  }
  return "";
}

TEST(BoundedRead, ReadsAWholeFileUpToItsLimit) {
  const fs::path path = fs::temp_directory_path() / "mfwave-bounded-read.txt";
  const std::string text(200000, 'x');  // several chunks
  std::ofstream(path, std::ios::binary) << text;
  EXPECT_EQ(readBoundedFile(path.string(), text.size(), "file", "the table"), text);
  EXPECT_EQ(refusal(path.string(), text.size() - 1),
            "cannot read the table '" + path.string() + "': larger than the limit of 199999 bytes");
  fs::remove(path);
}

TEST(BoundedRead, RefusesWhatIsNoRegularFileAndStopsAnEndlessOneAtTheLimit) {
  EXPECT_EQ(refusal("/nonexistent/table.csv", 100), "cannot read the table '/nonexistent/table.csv': no such file");
  EXPECT_EQ(refusal(fs::temp_directory_path().string(), 100),
            "cannot read the table '" + fs::temp_directory_path().string() + "': not a regular file");
  // /dev/zero is refused as no regular file; a /proc file reports size 0 and is read as it is.
  EXPECT_NE(refusal("/dev/zero", 100).find("not a regular file"), std::string::npos);
  if (fs::exists("/proc/self/status")) {
    EXPECT_GT(readBoundedFile("/proc/self/status", 1 << 20, "file", "the table").size(), 10u);
    EXPECT_NE(refusal("/proc/self/status", 10).find("larger than the limit of 10 bytes"), std::string::npos);
  }
}

}  // namespace
}  // namespace mfwave
