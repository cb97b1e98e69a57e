// --set key.path=value: TOML values and bare words, array-of-table indices, created tables,
// malformed overrides, and errors in overridden values located at "--set".

#include "io/scene/LoadScene.hpp"
#include "io/scene/Override.hpp"
#include "io/scene/Scene.hpp"
#include "SceneTestSupport.hpp"

#include <gtest/gtest.h>

namespace mfwave {
namespace {

using testing::readFully;
using testing::sceneErrorOf;
using testing::sceneTestFile;

Scene withOverrides(const std::vector<std::string>& overrides) {
  SceneReader reader = loadScene(sceneTestFile("valid/full-3d.toml"), overrides);
  return readFully(reader);
}

TEST(Override, NumbersStringsAndArrays) {
  const Scene s = withOverrides({"geometry.spacing=0.05", "scene.description=\"quoted text\"",
                                 "output.png_field=displacement", "geometry.upper=[2, 2, 1]",
                                 "output.vtk=false", "material.density = 1e3"});
  EXPECT_DOUBLE_EQ(s.geometry.spacing, 0.05);
  EXPECT_EQ(s.geometry.upper, (std::vector<Real>{2, 2, 1}));
  EXPECT_EQ(s.geometry.intervals, (std::vector<Index>{40, 40, 20}));
  EXPECT_EQ(s.info.description, "quoted text");
  EXPECT_EQ(s.output.pngField, "displacement");  // a bare word is a string
  EXPECT_FALSE(s.output.vtk);
  EXPECT_DOUBLE_EQ(s.material.density, 1000);
}

TEST(Override, ArrayOfTableIndicesAndInlineTables) {
  const Scene s = withOverrides({"probe[0].component=x", "probe[1].quantity=velocity",
                                 "probe[2]={ name = \"extra\", particle = 5, component = \"y\" }",
                                 "load[0].time_function={ type = \"triangle\", rise = 0.001 }",
                                 "boundary[0].faces=[\"-x\"]"});
  ASSERT_EQ(s.probes.size(), 3u);
  EXPECT_EQ(s.probes[0].component, 0);
  EXPECT_EQ(s.probes[1].quantity, ProbeQuantity::Velocity);
  EXPECT_EQ(s.probes[2].name, "extra");
  EXPECT_EQ(s.probes[2].particle, Index(5));
  EXPECT_EQ(s.loads[0].timeFunction.describe(), "triangle(start=0, rise=0.001, fall=0.001, amplitude=1)");
  EXPECT_EQ(s.boundaries[0].faces, std::vector<int>{0});
}

TEST(Override, CreatesMissingTablesAndEntries) {
  toml::table table = toml::parse("[scene]\nname = \"x\"\n");
  EXPECT_EQ(applyOverride(table, "stability.window=7"), "stability.window");
  EXPECT_EQ(applyOverride(table, "a.b.c=true"), "a.b.c");
  EXPECT_EQ(applyOverride(table, "probe[0].name=first"), "probe[0].name");
  EXPECT_EQ(applyOverride(table, "probe[1].name=second"), "probe[1].name");
  EXPECT_EQ(applyOverride(table, "probe[0].name=renamed"), "probe[0].name");
  EXPECT_EQ(table["stability"]["window"].value<std::int64_t>(), 7);
  EXPECT_EQ(table["a"]["b"]["c"].value<bool>(), true);
  ASSERT_TRUE(table["probe"].is_array());
  EXPECT_EQ(table["probe"].as_array()->size(), 2u);
  EXPECT_EQ(table["probe"][0]["name"].value<std::string>(), "renamed");
  EXPECT_EQ(table["probe"][1]["name"].value<std::string>(), "second");
  EXPECT_EQ(table["scene"]["name"].value<std::string>(), "x");
}

TEST(Override, MalformedOverridesReportSet) {
  for (const char* bad : {"geometry.spacing", "=1", "geometry..spacing=1", "probe[x].name=a", "probe[5].name=a",
                          "geometry.spacing.x=1", "geometry.lower=[1, 2", "scene.name=", "scene.name=\"open",
                          "scene.name.first=a", "probe.name=a"}) {
    const SceneError e = sceneErrorOf([&] { loadScene(sceneTestFile("valid/full-3d.toml"), {bad}); });
    EXPECT_EQ(e.key(), "--set") << bad << ": " << e.what();
    EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
  }
}

TEST(Override, BadOverriddenValueReportsSetAsItsSource) {
  SceneReader reader = loadScene(sceneTestFile("valid/full-3d.toml"), {"geometry.spacing=-0.5"});
  const SceneError e = sceneErrorOf([&] { readScene(reader); });
  EXPECT_EQ(e.key(), "geometry.spacing");
  EXPECT_EQ(e.location(), "--set");
  EXPECT_STREQ(e.what(), "--set: geometry.spacing: must be positive, got -0.5");
  // Keys inside an overridden table, and unknown keys set with --set, are located at --set too.
  SceneReader inside = loadScene(sceneTestFile("valid/full-3d.toml"),
                                 {"load[0].time_function={ type = \"ricker\" }"});
  const SceneError missing = sceneErrorOf([&] { readScene(inside); });
  EXPECT_EQ(missing.key(), "load[0].time_function.peak_frequency");
  EXPECT_EQ(missing.location(), "--set");
  SceneReader unknown = loadScene(sceneTestFile("valid/full-3d.toml"), {"output.evry=3"});
  readScene(unknown);
  const SceneError typo = sceneErrorOf([&] { unknown.checkAllKeysRead(); });
  EXPECT_EQ(typo.key(), "output.evry");
  EXPECT_STREQ(typo.what(), "--set: output.evry: unknown key; did you mean 'every'?");
  // A good override leaves the file's lines for the other keys.
  SceneReader other = loadScene(sceneTestFile("valid/full-3d.toml"), {"geometry.spacing=0.05", "scene.dimension=4"});
  const SceneError dimension = sceneErrorOf([&] { readScene(other); });
  EXPECT_EQ(dimension.location(), "--set");
  SceneReader fileLine = loadScene(sceneTestFile("valid/full-3d.toml"), {"geometry.spacing=0.05", "output.every=0"});
  EXPECT_EQ(sceneErrorOf([&] { readScene(fileLine); }).location(), "--set");
}

}  // namespace
}  // namespace mfwave
