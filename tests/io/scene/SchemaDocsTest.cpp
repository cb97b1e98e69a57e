// docs/scenes.md documents every key of the common schema and of the methods registered in lib/io/scene,
// so the docs cannot drift from the code.

#include "io/scene/IntegratorSpec.hpp"
#include "io/scene/SceneSchema.hpp"
#include "wiring/UpdatedLagrangianSphSpec.hpp"
#include "wiring/VeryWeakSphSpec.hpp"

#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

namespace mfwave {
namespace {

TEST(SceneDocs, EveryRegisteredKeyIsDocumented) {
  std::ifstream in(MFWAVE_SCENES_DOC);
  ASSERT_TRUE(in) << "cannot open " << MFWAVE_SCENES_DOC;
  std::stringstream text;
  text << in.rdbuf();
  const std::string docs = text.str();
  // One schema per SPH method: their option sets share key names (method.kernel) with other defaults.
  SceneSchema veryWeak = SceneSchema::common();
  addVeryWeakSphKeys(veryWeak);
  SceneSchema updatedLagrangian = SceneSchema::common();
  addUpdatedLagrangianSphKeys(updatedLagrangian);
  useFirstOrderIntegrators(updatedLagrangian);
  ASSERT_GT(veryWeak.keys().size(), 80u);
  for (const SceneSchema* schema : {&veryWeak, &updatedLagrangian})
    for (const auto& spec : schema->keys())
      EXPECT_NE(docs.find("`" + spec.path + "`"), std::string::npos) << spec.path << " is not in docs/scenes.md";
  // Every allowed value of the method names and of the integrator names is documented too.
  for (const SceneSchema* schema : {&veryWeak, &updatedLagrangian}) {
    for (const char* key : {"method.name", "integrator.name", "method.density"}) {
      const KeySpec* spec = schema->find(key);
      if (!spec) continue;
      for (const std::string& choice : spec->choices)
        EXPECT_NE(docs.find("`" + choice + "`"), std::string::npos) << key << " value " << choice
                                                                    << " is not in docs/scenes.md";
    }
  }
}

}  // namespace
}  // namespace mfwave
