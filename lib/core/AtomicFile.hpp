#pragma once
// Writes a file under a temporary name and renames it into place only when complete, so an
// interrupted run never leaves a truncated file that looks whole.

#include <fstream>
#include <string>

namespace mfwave {

class AtomicFile {
 public:
  // Opens "<path>.tmp-<pid>" for writing; throws Error naming the path if it cannot.
  explicit AtomicFile(std::string path);
  // Removes the temporary file if commit() was not called.
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ostream& stream() { return stream_; }
  // Flushes, closes and renames onto the final path; throws Error if any write failed.
  void commit();
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::string temporaryPath_;
  std::ofstream stream_;
  bool committed_ = false;
};

}  // namespace mfwave
