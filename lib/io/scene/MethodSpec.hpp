#pragma once
// [method]: the name of the spatial discretisation. Its options are the other keys of
// [method]; the method registers and reads them itself (reader.section("method")), after the
// common sections and before reader.checkAllKeysRead().

#include "io/scene/SceneReader.hpp"

#include <string>

namespace mfwave {

struct MethodSpec {
  std::string name;  // one of the schema's method.name choices (today "finite_difference")
};

MethodSpec readMethod(SceneReader& reader);

}  // namespace mfwave
