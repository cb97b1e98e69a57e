#pragma once
// A ParaView collection file (.pvd): the list of (time, frame file) pairs that makes a series of
// .vtp frames open as one time-dependent data set.

#include "core/Types.hpp"

#include <string>
#include <vector>

namespace mfwave {

class PvdCollection {
 public:
  struct Entry {
    Real time;
    std::string file;  // as written in the .pvd: relative to the .pvd's folder
  };

  // The collection at `path` (conventionally ending in .pvd). Nothing is written until add().
  explicit PvdCollection(std::string path);

  // Appends a frame and rewrites the whole .pvd atomically (AtomicFile), so an interrupted run
  // leaves a valid collection of the frames written so far. `file` is a path as the caller
  // opens it (absolute, or relative to the working directory); it is stored relative to the
  // .pvd's folder so the output folder can be moved or copied as a whole.
  void add(Real time, const std::string& file);

  const std::string& path() const { return path_; }
  const std::vector<Entry>& entries() const { return entries_; }
  // The entries of a run restored from a checkpoint; the file is rewritten at the next add().
  void restore(std::vector<Entry> entries) { entries_ = std::move(entries); }

 private:
  void rewrite() const;

  std::string path_;
  std::vector<Entry> entries_;
};

}  // namespace mfwave
