#include "core/AtomicFile.hpp"

#include "core/Error.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <unistd.h>

namespace mfwave {

AtomicFile::AtomicFile(std::string path)
    : path_(std::move(path)), temporaryPath_(path_ + ".tmp-" + std::to_string(::getpid())) {
  stream_.open(temporaryPath_, std::ios::out | std::ios::trunc | std::ios::binary);
  if (!stream_) throw Error("cannot open '" + temporaryPath_ + "' for writing: " + std::strerror(errno));
  stream_.precision(17);
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    stream_.close();
    std::remove(temporaryPath_.c_str());
  }
}

void AtomicFile::commit() {
  errno = 0;
  stream_.flush();
  const bool ok = static_cast<bool>(stream_);
  stream_.close();
  const int error = errno;  // the write's: a full disk (ENOSPC), a file size limit (EFBIG), ...
  if (!ok || stream_.fail())
    throw Error("writing '" + path_ + "' failed" + (error != 0 ? std::string(": ") + std::strerror(error) : "") +
                " (the file under that name is not touched)");
  if (std::rename(temporaryPath_.c_str(), path_.c_str()) != 0)
    throw Error("cannot rename '" + temporaryPath_ + "' to '" + path_ + "': " + std::strerror(errno));
  committed_ = true;
}

}  // namespace mfwave
