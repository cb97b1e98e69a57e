#pragma once
// The error of a scene file: where (file and line, or "--set"), which key path, what is wrong.
// It is an InputError whose key() is the full key path ("boundary[1].type"), so callers and
// tests can check which key was rejected; what() reads
//   scene.toml:12: geometry.spacing: must be positive, got -0.5
// Special keys: "(syntax)" for TOML syntax errors, "--set" for malformed overrides and
// "--scene" for a scene file that cannot be read.

#include "core/Error.hpp"

#include <string>

namespace mfwave {

class SceneError : public InputError {
 public:
  // `location`: "scene.toml:12", "scene.toml:3:7" (syntax), "--set", or "" (no location).
  SceneError(std::string location, std::string key, std::string problem)
      : InputError(key, problem),
        location_(std::move(location)),
        message_((location_.empty() ? "" : location_ + ": ") + key + ": " + problem) {}

  const char* what() const noexcept override { return message_.c_str(); }
  const std::string& location() const { return location_; }

 private:
  std::string location_;
  std::string message_;
};

}  // namespace mfwave
