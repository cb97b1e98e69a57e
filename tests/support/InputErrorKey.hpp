#pragma once
// Test helpers: run f and return the key (or the problem text) of the InputError it throws ("" if
// it throws none), so a test can assert that bad input names the right parameter and says why.

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

template <class F>
std::string inputErrorProblem(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.problem();
  }
  return "";
}

}  // namespace mfwave::testing
