// A scene that asks a method for what it cannot represent is refused before any work, naming the
// key and the methods that can.
#include "catalogue/MethodCatalogue.hpp"
#include "catalogue/SceneSupport.hpp"

#include "io/scene/LoadScene.hpp"

#include <gtest/gtest.h>

namespace mfwave {
namespace {

Scene sceneOf(const std::string& method, const std::string& load, int dimension = 3) {
  const std::string box = dimension == 3 ? "shape = \"block\"\nlower = [0.0, 0.0, 0.0]\nupper = [1.0, 1.0, 1.0]\n"
                                         : "shape = \"line\"\nlower = [0.0]\nupper = [1.0]\n";
  const std::string text = "[scene]\nname = \"t\"\ndimension = " + std::to_string(dimension) + "\n[geometry]\n" + box +
                           "spacing = 0.25\n[material]\ndensity = 1.0\nlambda = 1.0\nmu = 1.0\n[method]\nname = \"" +
                           method + "\"\n" + load + "[integrator]\nname = \"central_difference\"\nend_time = 1.0\n";
  SceneReader reader = parseScene(text, "test.toml", {}, catalogueSchema(methodNamed(method)));
  return readScene(reader);
}

const std::string kPointForce =
    "[[load]]\ntype = \"point_force\"\nposition = [0.5, 0.5, 0.5]\ndirection = [0.0, 0.0, 1.0]\n"
    "time_function = { type = \"ricker\", peak_frequency = 4.0, delay = 0.3 }\n";

TEST(SceneSupport, ASupportedSceneHasNoProblem) {
  EXPECT_TRUE(unsupportedFeatures(sceneOf("finite_difference", kPointForce), methodNamed("finite_difference")).empty());
}

TEST(SceneSupport, AnUnsupportedLoadNamesItsKeyAndTheMethodsThatTakeIt) {
  // (the very weak SPH takes point forces since issue 48: its cut-cell Galerkin variant in the solid study)
  const Scene scene = sceneOf("spectral_element", kPointForce);
  const auto problems = unsupportedFeatures(scene, methodNamed("spectral_element"));
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].key, "load[0].type");
  EXPECT_EQ(problems[0].supportedBy, (std::vector<std::string>{"finite_difference", "very_weak_sph"}));
  try {
    refuseUnsupported(scene, methodNamed("spectral_element"));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "load[0].type");
    EXPECT_NE(std::string(e.what()).find("spectral_element does not support point_force loads; supported by: "
                                         "finite_difference, very_weak_sph"),
              std::string::npos)
        << e.what();
  }
}

TEST(SceneSupport, RegionsCracksAndFixedSurfacesAreRefusedByNameForTheMethodsThatCannotRepresentThem) {
  EXPECT_TRUE(unsupportedSolidFeatures(methodNamed("very_weak_sph"), {true, false, false}).empty());
  EXPECT_TRUE(unsupportedSolidFeatures(methodNamed("reproducing_kernel"), {false, false, true}).empty());
  EXPECT_TRUE(unsupportedSolidFeatures(methodNamed("updated_lagrangian_sph"), {false, true, true}).empty());
  EXPECT_TRUE(unsupportedSolidFeatures(methodNamed("total_lagrangian_sph"), {false, true, true}).empty());
  for (const char* method : {"very_weak_sph", "reproducing_kernel"}) {
    const auto problems = unsupportedSolidFeatures(methodNamed(method), {false, true, false});
    ASSERT_EQ(problems.size(), 1u) << method;
    EXPECT_EQ(problems[0].key, "crack");
    EXPECT_EQ(problems[0].message(), std::string(method) + " does not support cracks; supported by: "
                                                           "updated_lagrangian_sph, total_lagrangian_sph");
  }
  for (const char* method : {"reproducing_kernel", "updated_lagrangian_sph", "total_lagrangian_sph"}) {
    const auto problems = unsupportedSolidFeatures(methodNamed(method), {true, false, false});
    ASSERT_EQ(problems.size(), 1u) << method;
    EXPECT_EQ(problems[0].key, "region");
    EXPECT_EQ(problems[0].message(), std::string(method) + " does not support materials by region; supported by: "
                                                           "very_weak_sph");
  }
  const auto fixed = unsupportedSolidFeatures(methodNamed("very_weak_sph"), {false, false, true});
  ASSERT_EQ(fixed.size(), 1u);
  EXPECT_EQ(fixed[0].key, "surface_boundary");
  EXPECT_EQ(fixed[0].message(), "very_weak_sph does not support fixed surfaces of a solid; supported by: "
                                "reproducing_kernel, updated_lagrangian_sph, total_lagrangian_sph");
}

TEST(SceneSupport, DimensionAndIntegratorAreCheckedToo) {
  const Scene line = sceneOf("radial_basis", "", 1);
  EXPECT_TRUE(unsupportedFeatures(line, methodNamed("radial_basis")).empty());
  const auto inSpace = unsupportedFeatures(sceneOf("finite_difference", ""), methodNamed("radial_basis"));
  ASSERT_GE(inSpace.size(), 2u);
  EXPECT_EQ(inSpace[0].key, "scene.dimension");
  EXPECT_EQ(inSpace[1].key, "geometry.shape");
  // The spectral elements take central differences only.
  Scene newmark = sceneOf("spectral_element", "");
  newmark.integrator.name = "newmark";
  const auto problems = unsupportedFeatures(newmark, methodNamed("spectral_element"));
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].key, "integrator.name");
  EXPECT_NE(std::find(problems[0].supportedBy.begin(), problems[0].supportedBy.end(), "reproducing_kernel"),
            problems[0].supportedBy.end());
}

}  // namespace
}  // namespace mfwave
