#include "core/StateArchive.hpp"

#include "core/Error.hpp"

#include <cmath>

namespace mfwave {

StateArchive::StateArchive() : arrays_(std::make_shared<Arrays>()) {}
StateArchive::StateArchive(Arrays arrays) : arrays_(std::make_shared<Arrays>(std::move(arrays))) {}
StateArchive::StateArchive(std::shared_ptr<Arrays> arrays, std::string prefix)
    : arrays_(std::move(arrays)), prefix_(std::move(prefix)) {}

StateArchive StateArchive::section(const std::string& name) const { return {arrays_, prefix_ + name + "."}; }

void StateArchive::put(const std::string& name, std::vector<Real> values) {
  const std::string key = full(name);
  for (auto& entry : *arrays_)
    if (entry.first == key) {
      entry.second = std::move(values);
      return;
    }
  arrays_->emplace_back(key, std::move(values));
}

void StateArchive::put(const std::string& name, const Vector& values) {
  put(name, std::vector<Real>(values.data(), values.data() + values.size()));
}

void StateArchive::putText(const std::string& name, const std::string& text) {
  std::vector<Real> bytes;
  bytes.reserve(text.size());
  for (const char c : text) bytes.push_back(static_cast<Real>(static_cast<unsigned char>(c)));
  put(name, std::move(bytes));
}

std::string StateArchive::text(const std::string& name) const {
  std::string text;
  for (const Real byte : get(name)) {
    if (!(byte >= 0 && byte <= 255) || byte != std::floor(byte))
      throw InputError("--restart", "the checkpoint's text '" + full(name) + "' holds a value that is no byte");
    text += static_cast<char>(static_cast<unsigned char>(byte));
  }
  return text;
}

bool StateArchive::has(const std::string& name) const {
  const std::string key = full(name);
  for (const auto& entry : *arrays_)
    if (entry.first == key) return true;
  return false;
}

const std::vector<Real>& StateArchive::get(const std::string& name) const {
  const std::string key = full(name);
  for (const auto& entry : *arrays_)
    if (entry.first == key) return entry.second;
  throw InputError("--restart", "the checkpoint has no array '" + key +
                                    "': it was written by another build or another setup of this scene");
}

void StateArchive::get(const std::string& name, Vector& values) const {
  const std::vector<Real>& stored = get(name);
  if (static_cast<Index>(stored.size()) != values.size())
    throw InputError("--restart", "the checkpoint's array '" + full(name) + "' holds " +
                                      std::to_string(stored.size()) + " values where this run has " +
                                      std::to_string(values.size()));
  for (Index i = 0; i < values.size(); ++i) values[i] = stored[static_cast<std::size_t>(i)];
}

void StateArchive::getResized(const std::string& name, Vector& values) const {
  const std::vector<Real>& stored = get(name);
  values.resize(static_cast<Index>(stored.size()));
  for (Index i = 0; i < values.size(); ++i) values[i] = stored[static_cast<std::size_t>(i)];
}

const std::vector<Real>& StateArchive::numbers(const std::string& name, std::size_t count) const {
  const std::vector<Real>& stored = get(name);
  if (stored.size() != count)
    throw InputError("--restart", "the checkpoint's '" + full(name) + "' holds " + std::to_string(stored.size()) +
                                      " values, not " + (count == 1 ? std::string("one") : std::to_string(count)));
  return stored;
}

Real StateArchive::scalar(const std::string& name) const { return numbers(name, 1)[0]; }

long StateArchive::integer(const std::string& name) const {
  const Real x = scalar(name);
  if (!(std::abs(x) < 9.0e15) || x != std::floor(x))
    throw InputError("--restart", "the checkpoint's '" + full(name) + "' is not a whole number");
  return static_cast<long>(x);
}

}  // namespace mfwave
