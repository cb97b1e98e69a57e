#include "io/scene/MethodSpec.hpp"

namespace mfwave {

MethodSpec readMethod(SceneReader& reader) {
  reader.table("method", true);
  return MethodSpec{reader.string("method.name")};
}

}  // namespace mfwave
