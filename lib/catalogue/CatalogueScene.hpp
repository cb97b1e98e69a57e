#pragma once
// A scene read through the catalogue, outside any study: the common sections and the [method] keys of
// the method it names (catalogueSchema), the method's choice, and what the method cannot represent
// refused before any work. The study program that runs the scene reads its own keys ([study]) and
// checks every key; this reader leaves those to it.

#include "catalogue/ScenePrediction.hpp"
#include "io/scene/Scene.hpp"

#include <optional>
#include <string>
#include <vector>

namespace mfwave {

struct CatalogueScene {
  Scene scene;
  MethodChoice choice;
  std::vector<std::string> notes;  // what was read differently from the scene, and why
};

// Reads `path` with the overrides. Returns nothing for a tool scene (no [scene] section: it has no
// method or geometry to plan). Throws SceneError / InputError naming the key: an unknown method
// (with the catalogue's names), a feature the method does not support (with the methods that do).
// A first-order method (the UL-SPH) on a scene that names a second-order integrator is read with
// leapfrog, as the Lamb study steps it, and a note says so.
std::optional<CatalogueScene> readCatalogueScene(const std::string& path, const std::vector<std::string>& overrides);

}  // namespace mfwave
