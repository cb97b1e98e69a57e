#pragma once
// The method catalogue: every discretisation mfwave offers, registered once (MethodCatalogue.cpp),
// under the one name scenes, tools, the speed-accuracy sweep and the docs use. `mfwave methods`
// prints it; `mfwave check` and `mfwave plan` read a scene's method through it; SceneSupport.hpp
// refuses what a method cannot represent.

#include "catalogue/MethodEntry.hpp"

#include <string>
#include <vector>

namespace mfwave {

// Every entry, in the order `mfwave methods` lists them.
const std::vector<MethodEntry>& methodCatalogue();

// The entry named `name`; nullptr when there is none.
const MethodEntry* findMethod(const std::string& name);

// The entry named `name`. Throws InputError(key) naming the catalogue's methods (and the closest
// one to a likely typo) when there is none.
const MethodEntry& methodNamed(const std::string& name, const std::string& key = "method.name");

// Every method name, in catalogue order.
std::vector<std::string> methodNames();

// Whether `program` runs the method (its entry names it among its programs).
bool runsIn(const MethodEntry& method, const std::string& program);

// The catalogue's methods that `program` runs, in catalogue order.
std::vector<std::string> methodsRunBy(const std::string& program);

// The schema a scene of `method` is read with outside its study: the common sections, every
// catalogue name as a method.name choice, the first-order integrator names for a first-order
// method, and the method's own [method] keys.
SceneSchema catalogueSchema(const MethodEntry& method);

}  // namespace mfwave
