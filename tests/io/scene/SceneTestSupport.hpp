#pragma once
// Helpers shared by the scene tests: paths from compile definitions, running the full read.

#include "io/scene/LoadScene.hpp"
#include "io/scene/Scene.hpp"

#include <functional>
#include <string>

namespace mfwave::testing {

inline std::string sceneTestFile(const std::string& name) { return std::string(MFWAVE_SCENE_TEST_DIR) + "/" + name; }

// Everything a driver does before any work: common sections, then the unknown-key check.
inline Scene readFully(SceneReader& reader) {
  Scene scene = readScene(reader);
  reader.checkAllKeysRead();
  return scene;
}

// Runs f and returns the SceneError it throws (with an empty key if it throws none).
inline SceneError sceneErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const SceneError& e) {
    return e;
  }
  return SceneError("", "", "no SceneError was thrown");
}

}  // namespace mfwave::testing
