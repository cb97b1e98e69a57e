#pragma once
// Test helper: runs f and returns the key of the InputError it throws ("" if it throws none),
// so a test can assert that bad input names the right parameter.

#include "core/Error.hpp"

#include <string>

namespace mfwave::testing {

template <class F>
std::string inputErrorKey(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.key();
  }
  return "";
}

}  // namespace mfwave::testing
