// docs/scenes.md documents every key of the common schema and of the methods registered in lib/io/scene,
// so the docs cannot drift from the code.

#include "io/scene/SceneSchema.hpp"
#include "io/scene/VeryWeakSphSpec.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace mfwave {
namespace {

TEST(SceneDocs, EveryRegisteredKeyIsDocumented) {
  std::ifstream in(MFWAVE_SCENES_DOC);
  ASSERT_TRUE(in) << "cannot open " << MFWAVE_SCENES_DOC;
  std::stringstream text;
  text << in.rdbuf();
  const std::string docs = text.str();
  SceneSchema schema = SceneSchema::common();
  addVeryWeakSphKeys(schema);
  ASSERT_GT(schema.keys().size(), 80u);
  for (const auto& spec : schema.keys())
    EXPECT_NE(docs.find("`" + spec.path + "`"), std::string::npos) << spec.path << " is not in docs/scenes.md";
}

}  // namespace
}  // namespace mfwave
