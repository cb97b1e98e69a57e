#include "observers/Observer.hpp"

#include "core/Error.hpp"

#include <cxxabi.h>

#include <cstdlib>
#include <memory>
#include <typeinfo>

namespace mfwave {
namespace {

std::string typeName(const Observer& observer) {
  const char* mangled = typeid(observer).name();
  int status = 0;
  std::unique_ptr<char, void (*)(void*)> name(abi::__cxa_demangle(mangled, nullptr, nullptr, &status), std::free);
  return status == 0 && name ? name.get() : mangled;
}

}  // namespace

void Observer::saveState(StateArchive&) const {
  throw Error("the observer " + typeName(*this) + " cannot be checkpointed yet");
}

void Observer::restoreState(const StateArchive&) {
  throw Error("the observer " + typeName(*this) + " cannot be checkpointed yet");
}

}  // namespace mfwave
