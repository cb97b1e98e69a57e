// The Lamb study's plan, in the library: the methods it runs come from the catalogue, each has its
// reader, and a scene's cases are planned without the driver.
#include "studies/lamb3d/LambPlan.hpp"

#include "catalogue/MethodCatalogue.hpp"
#include "io/scene/LoadScene.hpp"

#include <gtest/gtest.h>

namespace mfwave::lamb3d {
namespace {

Plan planOf(const std::string& file, int dimension, const std::vector<std::string>& overrides) {
  SceneReader reader = loadScene(std::string(SCENES_FOLDER) + "/" + file, overrides, lambSchema(dimension));
  Plan plan = dimension == 3 ? readLambPlan<3>(reader) : readLambPlan<2>(reader);
  reader.checkAllKeysRead();
  return plan;
}

TEST(LambPlan, TheStudyRunsTheCatalogueMethodsThatNameIt) {
  const std::vector<std::string> expected = {"very_weak_sph", "reproducing_kernel", "spectral_element",
                                             "updated_lagrangian_sph"};
  EXPECT_EQ(lambMethods(3), expected);
  EXPECT_EQ(lambMethods(2), expected);
  const SceneSchema schema = lambSchema(3);
  const auto& choices = schema.at("method.name").choices;
  for (const std::string& name : expected)
    EXPECT_NE(std::find(choices.begin(), choices.end(), name), choices.end()) << name;
}

TEST(LambPlan, EveryMethodOfTheStudyHasAReader) {
  const std::vector<std::pair<std::string, std::string>> first = {
      {"very_weak_sph", "galerkin_0.5"},
      {"reproducing_kernel", "rk_m2_a2.2_0.5"},
      {"spectral_element", "sem_n2_0.5"},
      {"updated_lagrangian_sph", "ulsph_0.5"}};
  for (const auto& [method, name] : first) {
    std::vector<std::string> sets = {"method.name=" + method, "study.spacings=[0.5]"};
    if (method == "reproducing_kernel" || method == "spectral_element") sets.push_back("method.order=2");
    const Plan plan = planOf("lamb3d.toml", 3, sets);
    ASSERT_FALSE(plan.cases.empty()) << method;
    EXPECT_EQ(plan.cases.front().name, name) << method;
    EXPECT_TRUE(plan.cases.front().writeFrames) << method;
  }
}

TEST(LambPlan, TheDefaultSceneComparesThePublishedScheme) {
  // lamb3d.toml: Galerkin and the published scheme at dx = 0.5, the free block, at every spacing.
  const Plan plan = planOf("lamb3d.toml", 3, {});
  ASSERT_GE(plan.cases.size(), 3u);
  EXPECT_EQ(plan.cases[0].name, "galerkin_0.5");
  EXPECT_EQ(plan.cases[1].name, "published_0.5");
  EXPECT_EQ(plan.study.scene.info.dimension, 3);
}

TEST(LambPlan, AMethodOutsideTheStudyIsRefusedByName) {
  try {
    planOf("lamb2d.toml", 2, {"method.name=finite_difference"});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "method.name");
  }
}

}  // namespace
}  // namespace mfwave::lamb3d
