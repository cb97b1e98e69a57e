#pragma once
// Named arrays of numbers: what an integrator, a system or an observer hands a checkpoint so that
// a run can go on later exactly as if it had never stopped (issue 20). Each part writes and reads
// its own section ("integrator.u", "observer.2.times"); counts and flags are stored as numbers
// (exact: every integer below 2^53 is a double).
//
// The parts never see files: io/checkpoint turns an archive into bytes and back.

#include "core/Types.hpp"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace mfwave {

class StateArchive {
 public:
  using Arrays = std::vector<std::pair<std::string, std::vector<Real>>>;

  StateArchive();
  explicit StateArchive(Arrays arrays);

  // A view of the same storage whose names are prefixed with `name` + ".".
  StateArchive section(const std::string& name) const;

  void put(const std::string& name, std::vector<Real> values);
  void put(const std::string& name, const Vector& values);
  void putScalar(const std::string& name, Real value) { put(name, std::vector<Real>{value}); }
  void putText(const std::string& name, const std::string& text);  // one number per byte

  bool has(const std::string& name) const;
  // Throw InputError("--restart", ...) naming the array when it is missing or, for the sized
  // forms, of another length than expected (a checkpoint of another system).
  const std::vector<Real>& get(const std::string& name) const;
  void get(const std::string& name, Vector& values) const;                 // values keeps its size
  void getResized(const std::string& name, Vector& values) const;          // values takes the array's size
  const std::vector<Real>& numbers(const std::string& name, std::size_t count) const;  // exactly `count` values
  Real scalar(const std::string& name) const;
  long integer(const std::string& name) const;  // a scalar that must be a whole number
  std::string text(const std::string& name) const;

  // Every array of the whole archive (all sections), in the order put.
  const Arrays& arrays() const { return *arrays_; }

 private:
  StateArchive(std::shared_ptr<Arrays> arrays, std::string prefix);
  std::string full(const std::string& name) const { return prefix_ + name; }

  std::shared_ptr<Arrays> arrays_;
  std::string prefix_;
};

}  // namespace mfwave
