#pragma once
// [scene]: what the study is called and its dimension.

#include "io/scene/SceneReader.hpp"

#include <string>

namespace mfwave {

struct SceneInfo {
  std::string name;         // required; the default output folder is out/<name>
  std::string description;  // optional
  int dimension = 0;        // 1, 2 or 3
};

SceneInfo readSceneInfo(SceneReader& reader);

}  // namespace mfwave
