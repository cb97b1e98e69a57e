#pragma once
// The project's exceptions. Every message names what was wrong and, for input, which key.

#include <stdexcept>
#include <string>

namespace mfwave {

// Base of all mfwave errors.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Bad input: a parameter out of range, a malformed scene, an inconsistent combination.
// `key` is the parameter or scene key path ("material.poisson_ratio"); `problem` says what is wrong.
class InputError : public Error {
 public:
  InputError(std::string key, std::string problem)
      : Error(key + ": " + problem), key_(std::move(key)), problem_(std::move(problem)) {}
  const std::string& key() const { return key_; }
  // The problem alone, so that a layer that knows where the key was written (the scene reader)
  // can say it again with the file and line.
  const std::string& problem() const { return problem_; }

 private:
  std::string key_;
  std::string problem_;
};

// A run that became unstable: non-finite values or runaway growth.
class InstabilityError : public Error {
 public:
  InstabilityError(const std::string& what, long step, double time, long particle)
      : Error(what), step_(step), time_(time), particle_(particle) {}
  long step() const { return step_; }
  double time() const { return time_; }
  long particle() const { return particle_; }

 private:
  long step_;
  double time_;
  long particle_;
};

}  // namespace mfwave
