// The typed common sections, defaults in the resolved scene, the deferred-option and driver-key
// mechanisms, and the particles built from a scene.

#include "io/scene/BuildParticles.hpp"
#include "io/scene/LoadScene.hpp"
#include "io/scene/Scene.hpp"
#include "particles/BoxFace.hpp"
#include "SceneTestSupport.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace mfwave {
namespace {

using testing::readFully;
using testing::sceneErrorOf;
using testing::sceneTestFile;

const std::string kMinimal = R"(
[scene]
name = "minimal"
dimension = 1
[geometry]
shape = "line"
lower = [0.0]
upper = [1.0]
spacing = 0.25
[material]
density = 1.0
lambda = 1.0
mu = 1.0
[method]
name = "finite_difference"
[integrator]
end_time = 1.0
)";

void expectFullScene(const Scene& s) {
  EXPECT_EQ(s.info.name, "full");
  EXPECT_EQ(s.info.description, "every section");
  EXPECT_EQ(s.info.dimension, 3);

  const GeometrySpec& g = s.geometry;
  EXPECT_EQ(g.shape, "block");
  EXPECT_EQ(g.upper, (std::vector<Real>{1.0, 2.0, 0.5}));
  EXPECT_DOUBLE_EQ(g.spacing, 0.1);
  EXPECT_EQ(g.intervals, (std::vector<Index>{10, 20, 5}));
  EXPECT_EQ(g.particleCount(), 11 * 21 * 6);
  EXPECT_EQ(g.ghostLayers, 2);
  EXPECT_EQ(g.ghostFaces, faceBit(BoxFace::MinusZ));
  EXPECT_EQ(g.periodic, (std::vector<bool>{false, true, false}));

  // E = 70 GPa, nu = 0.25: mu = E / 2.5 = 28 GPa, lambda = E nu / ((1 + nu)(1 - 2 nu)) = 28 GPa.
  EXPECT_NEAR(s.material.mu, 28e9, 1e-3);
  EXPECT_NEAR(s.material.lambda, 28e9, 1e-3);
  EXPECT_DOUBLE_EQ(s.material.density, 2700);
  EXPECT_TRUE(s.material.givenAsYoung);
  EXPECT_EQ(s.method.name, "finite_difference");

  ASSERT_EQ(s.boundaries.size(), 3u);
  EXPECT_EQ(s.boundaries[0].type, BoundaryType::Fixed);
  EXPECT_EQ(s.boundaries[0].faces, (std::vector<int>{0, 1}));
  EXPECT_EQ(facesWith(s.boundaries, BoundaryType::Fixed), faceBit(BoxFace::MinusX) | faceBit(BoxFace::PlusX));
  EXPECT_EQ(s.boundaries[1].type, BoundaryType::Traction);
  EXPECT_EQ(s.boundaries[1].traction, (std::vector<Real>{0, 0, -1e6}));
  EXPECT_DOUBLE_EQ(s.boundaries[1].timeFunction(0.0005), 0.5);  // ramp over 1 ms
  EXPECT_DOUBLE_EQ(s.boundaries[1].timeFunction(0.002), 1.0);
  EXPECT_EQ(s.boundaries[2].type, BoundaryType::Displacement);
  EXPECT_EQ(s.boundaries[2].value, (std::vector<Real>{0, 0, 1e-3}));
  EXPECT_EQ(s.boundaries[2].timeFunction.kind(), TimeFunction::Kind::Tabulated);
  EXPECT_DOUBLE_EQ(s.boundaries[2].timeFunction(0.0015), 0.5);  // pulse.csv: 0 -> 1 -> 0

  ASSERT_EQ(s.loads.size(), 2u);
  EXPECT_EQ(s.loads[0].type, LoadType::PointForce);
  EXPECT_EQ(s.loads[0].direction, (std::vector<Real>{0, 0, 1}));  // normalised
  EXPECT_DOUBLE_EQ(s.loads[0].amplitude, 1000);
  EXPECT_EQ(s.loads[0].timeFunction.describe(), "ricker(peak_frequency=5000, delay=0.0003, amplitude=1)");
  EXPECT_EQ(s.loads[1].type, LoadType::BodyForce);
  EXPECT_EQ(s.loads[1].value, (std::vector<Real>{0, 0, -26487}));
  EXPECT_EQ(s.loads[1].timeFunction.describe(), "constant(value=1)");

  EXPECT_EQ(s.integrator.name, "newmark");
  EXPECT_DOUBLE_EQ(s.integrator.endTime, 0.002);
  ASSERT_TRUE(s.integrator.timeStep.has_value());
  EXPECT_DOUBLE_EQ(*s.integrator.timeStep, 1e-5);
  EXPECT_EQ(s.integrator.stepsFor(1.0), 200);
  EXPECT_DOUBLE_EQ(s.integrator.options.newmarkBeta, 0.3025);
  EXPECT_DOUBLE_EQ(s.integrator.options.newmarkGamma, 0.6);

  ASSERT_EQ(s.probes.size(), 2u);
  EXPECT_EQ(s.probes[0].name, "centre");
  ASSERT_TRUE(s.probes[0].position.has_value());
  EXPECT_EQ(*s.probes[0].position, (std::vector<Real>{0.52, 1.0, 0.26}));
  EXPECT_EQ(s.probes[0].quantity, ProbeQuantity::Velocity);
  EXPECT_EQ(s.probes[0].component, 2);
  EXPECT_FALSE(s.probes[1].position.has_value());
  EXPECT_EQ(s.probes[1].particle, Index(0));
  EXPECT_EQ(s.probes[1].quantity, ProbeQuantity::Displacement);
  EXPECT_EQ(s.probes[1].component, 0);

  EXPECT_EQ(s.output.folder, "results/full");
  EXPECT_EQ(s.output.every, 20);
  EXPECT_TRUE(s.output.vtk);
  EXPECT_FALSE(s.output.png);
  EXPECT_EQ(s.output.pngComponent, "z");
  EXPECT_EQ(s.output.pngComponentIndex, 2);
  EXPECT_EQ(s.output.pngField, "velocity");
  EXPECT_EQ(s.output.pngWidth, 1024);
  EXPECT_EQ(s.output.pngHeight, 768);
  EXPECT_EQ(s.output.probeEvery, 1);
  EXPECT_TRUE(s.output.energy);

  EXPECT_EQ(s.stability.window, 100);
  EXPECT_DOUBLE_EQ(s.stability.growthFactor, 1e3);
  EXPECT_TRUE(std::isinf(s.stability.absoluteLimit));
  EXPECT_EQ(s.stability.options(3, 0).components, 3);
}

TEST(SceneReader, FullSceneParsesIntoTypedValues) {
  SceneReader reader = loadScene(sceneTestFile("valid/full-3d.toml"));
  expectFullScene(readFully(reader));
}

TEST(SceneReader, DefaultsAreInsertedIntoTheResolvedScene) {
  SceneReader reader = loadScene(sceneTestFile("valid/full-3d.toml"));
  readFully(reader);
  const std::string resolved = reader.resolvedToml();
  for (const char* expected :
       {"delay = 0.0003", "absolute_limit = inf", "growth_factor = 1000.0", "probe_every = 1",
        "png_width = 1024", "quantity = \"velocity\"", "time_function = { type = \"constant\", value = 1.0 }",
        "time_function = { type = \"ramp\", start = 0.0, duration = 0.001, amplitude = 1.0 }",
        "periodic = [false, true, false]", "spacing = 0.1", "\n[[boundary]]\n", "\n[stability]\ngrowth_factor = 1000.0\nwindow = 100\nabsolute_limit = inf\n"})
    EXPECT_NE(resolved.find(expected), std::string::npos) << expected << "\n" << resolved;
  // The CSV path is made absolute, so the resolved scene works from the output folder.
  const std::string csv = std::filesystem::absolute(sceneTestFile("valid/pulse.csv")).lexically_normal().string();
  EXPECT_NE(resolved.find("file = \"" + csv + "\""), std::string::npos) << resolved;
  // Keys not given stay out when they are mutually exclusive with given ones.
  EXPECT_EQ(resolved.find("cfl"), std::string::npos);
  // Sections in schema order.
  EXPECT_LT(resolved.find("[scene]"), resolved.find("[geometry]"));
  EXPECT_LT(resolved.find("[integrator]"), resolved.find("[[probe]]"));
}

TEST(SceneReader, ResolvedSceneReparsesToTheSameScene) {
  SceneReader first = loadScene(sceneTestFile("valid/full-3d.toml"));
  readFully(first);
  const std::string resolved = first.resolvedToml();
  SceneReader second = parseScene(resolved, "scene.resolved.toml");
  expectFullScene(readFully(second));
  // Resolving is idempotent: the second resolution equals the first below the header line.
  const std::string again = second.resolvedToml();
  EXPECT_EQ(resolved.substr(resolved.find('\n')), again.substr(again.find('\n')));
}

TEST(SceneReader, MinimalSceneGetsEveryDefault) {
  SceneReader reader = parseScene(kMinimal, "minimal.toml");
  const Scene s = readFully(reader);
  EXPECT_EQ(s.integrator.name, "central_difference");
  EXPECT_DOUBLE_EQ(s.integrator.cfl, 0.5);
  EXPECT_FALSE(s.integrator.timeStep.has_value());
  EXPECT_EQ(s.output.folder, "out/minimal");
  EXPECT_EQ(s.output.every, 10);
  EXPECT_EQ(s.geometry.ghostFaces, 0);
  EXPECT_EQ(s.geometry.periodic, std::vector<bool>{false});
  EXPECT_TRUE(s.boundaries.empty());
  const std::string resolved = reader.resolvedToml();
  for (const char* expected : {"cfl = 0.5", "name = \"central_difference\"", "folder = \"out/minimal\"",
                               "ghost_faces = []", "periodic = [false]", "[output]", "[stability]"})
    EXPECT_NE(resolved.find(expected), std::string::npos) << expected << "\n" << resolved;
  // Newmark and ARKODE keys belong to other integrators: not inserted.
  EXPECT_EQ(resolved.find("newmark_beta"), std::string::npos);
  EXPECT_EQ(resolved.find("arkode"), std::string::npos);
}

TEST(SceneReader, ComputedDefaultsFollowOtherKeys) {
  SceneReader reader = parseScene(kMinimal + R"(
[[load]]
type = "point_force"
position = [0.5]
direction = [-3.0]
time_function = { type = "triangle", rise = 0.2 }
[[load]]
type = "point_force"
position = [0.5]
direction = [1.0]
time_function = { type = "ricker", peak_frequency = 2.0 }
)",
                                  "loads.toml");
  const Scene s = readFully(reader);
  EXPECT_EQ(s.loads[0].direction, std::vector<Real>{-1.0});
  EXPECT_EQ(s.loads[0].timeFunction.describe(), "triangle(start=0, rise=0.2, fall=0.2, amplitude=1)");
  EXPECT_EQ(s.loads[1].timeFunction.describe(), "ricker(peak_frequency=2, delay=0.75, amplitude=1)");
  EXPECT_LT(std::abs(s.loads[1].timeFunction(0.0)), 1e-8);  // the default delay starts near zero
}

TEST(SceneReader, GhostFacesDefaultToAllFacesWhenGhostLayersArePositive) {
  std::string text = kMinimal;
  text.replace(text.find("spacing = 0.25"), 14, "spacing = 0.25\nghost_layers = 2");
  SceneReader reader = parseScene(text, "ghosts.toml");
  const Scene s = readFully(reader);
  EXPECT_EQ(s.geometry.ghostFaces, allFaces(1));
  EXPECT_NE(reader.resolvedToml().find("ghost_faces = [\"-x\", \"+x\"]"), std::string::npos);
  // 5 lattice particles and 2 ghost layers on each end.
  const ParticleSet<1> particles = buildParticles<1>(s.geometry);
  EXPECT_EQ(particles.physicalCount(), 5);
  EXPECT_EQ(particles.ghostCount(), 4);
  EXPECT_THROW(buildParticles<2>(s.geometry), std::invalid_argument);
}

TEST(SceneReader, MethodOptionsAreReadLaterAndCheckedAtTheEnd) {
  SceneSchema schema = SceneSchema::common();
  schema.add("method.order", ValueType::Integer).withUnit("-").defaultsTo("2").between(2, 8)
      .describedAs("order of the stencil");
  std::string text = kMinimal;
  text.replace(text.find("name = \"finite_difference\""), 26, "name = \"finite_difference\"\norder = 4");
  {
    SceneReader reader = parseScene(text, "deferred.toml", {}, schema);
    readScene(reader);
    // The method has not read its option yet: the final check would report it.
    const SceneError early = sceneErrorOf([&] { reader.checkAllKeysRead(); });
    EXPECT_EQ(early.key(), "method.order");
    EXPECT_EQ(reader.section("method").integer("order"), 4);
    EXPECT_NO_THROW(reader.checkAllKeysRead());
  }
  {
    std::string typo = text;
    typo.replace(typo.find("order = 4"), 9, "ordr = 4");
    SceneReader reader = parseScene(typo, "typo.toml", {}, schema);
    readScene(reader);
    EXPECT_EQ(reader.section("method").integer("order"), 2);  // the default
    const SceneError e = sceneErrorOf([&] { reader.checkAllKeysRead(); });
    EXPECT_EQ(e.key(), "method.ordr");
    EXPECT_NE(std::string(e.what()).find("did you mean 'order'?"), std::string::npos) << e.what();
  }
  {
    std::string bad = text;
    bad.replace(bad.find("order = 4"), 9, "order = 9");
    SceneReader reader = parseScene(bad, "bad.toml", {}, schema);
    readScene(reader);
    const SceneError e = sceneErrorOf([&] { reader.section("method").integer("order"); });
    EXPECT_STREQ(e.what(), "bad.toml:16: method.order: must lie in [2, 8], got 9");
  }
}

TEST(SceneReader, DriverRegistersItsOwnStudyKeys) {
  const std::string text = kMinimal + "\n[study]\ncells = [32, 64]\nmode = 2\n";
  {
    SceneReader reader = parseScene(text, "study.toml");  // common schema only
    readScene(reader);
    const SceneError e = sceneErrorOf([&] { reader.checkAllKeysRead(); });
    EXPECT_EQ(e.key(), "study");
    EXPECT_NE(std::string(e.what()).find("unknown key"), std::string::npos);
  }
  SceneSchema schema = SceneSchema::common();
  schema.add("study", ValueType::Table).describedAs("the convergence study");
  schema.add("study.cells", ValueType::NumberArray).withUnit("-").required().describedAs("cells per case");
  schema.add("study.mode", ValueType::Integer).withUnit("-").defaultsTo("1").atLeast(1).describedAs("mode");
  schema.add("study.length", ValueType::Number).withUnit("m").defaultsTo("1.0").positive().describedAs("length");
  SceneReader reader = parseScene(text, "study.toml", {}, schema);
  readScene(reader);
  EXPECT_EQ(reader.numbers("study.cells"), (std::vector<Real>{32, 64}));
  EXPECT_EQ(reader.integer("study.mode"), 2);
  EXPECT_DOUBLE_EQ(reader.number("study.length"), 1.0);
  EXPECT_NO_THROW(reader.checkAllKeysRead());
  EXPECT_NE(reader.resolvedToml().find("[study]\ncells = [32, 64]\nmode = 2\nlength = 1.0\n"), std::string::npos)
      << reader.resolvedToml();
  EXPECT_NE(reader.schema().describe().find("study.cells"), std::string::npos);
  // Reading a key nobody registered is a programming error, not an input error.
  EXPECT_THROW(reader.number("study.unregistered"), std::logic_error);
}

TEST(SceneReader, ErrorsNameFileLineAndKeyPath) {
  std::string text = kMinimal;
  text.replace(text.find("spacing = 0.25"), 14, "spacing = -0.5");
  SceneReader reader = parseScene(text, "scene.toml");
  const SceneError e = sceneErrorOf([&] { readScene(reader); });
  EXPECT_STREQ(e.what(), "scene.toml:9: geometry.spacing: must be positive, got -0.5");
  EXPECT_EQ(e.key(), "geometry.spacing");
  EXPECT_EQ(e.location(), "scene.toml:9");
  // A missing key is located at its parent table.
  std::string missing = kMinimal;
  missing.erase(missing.find("end_time = 1.0"), 14);
  SceneReader second = parseScene(missing, "scene.toml");
  const SceneError m = sceneErrorOf([&] { readScene(second); });
  EXPECT_EQ(m.key(), "integrator.end_time");
  EXPECT_EQ(m.location(), "scene.toml:16");
}

TEST(SceneReader, UnreadableFileAndSyntaxErrors) {
  const SceneError missing = sceneErrorOf([] { loadScene("/nonexistent/scene.toml"); });
  EXPECT_EQ(missing.key(), "--scene");
  EXPECT_NE(std::string(missing.what()).find("/nonexistent/scene.toml"), std::string::npos);
  const SceneError folder = sceneErrorOf([] { loadScene(MFWAVE_SCENE_TEST_DIR); });
  EXPECT_EQ(folder.key(), "--scene");
  const SceneError syntax = sceneErrorOf([] { parseScene("[scene]\nname = \"x\"\ndimension = = 2\n", "s.toml"); });
  EXPECT_EQ(syntax.key(), "(syntax)");
  EXPECT_EQ(syntax.location().rfind("s.toml:3:", 0), 0u) << syntax.what();
}

TEST(SceneReader, BlockRickerExampleBuildsItsParticles) {
  SceneReader reader = loadScene(std::string(MFWAVE_SCENE_DATA_DIR) + "/block-ricker.toml");
  const Scene s = readFully(reader);
  EXPECT_EQ(s.geometry.particleCount(), 9261);
  EXPECT_EQ(facesWith(s.boundaries, BoundaryType::Fixed), allFaces(3));
  EXPECT_EQ(s.loads[0].timeFunction.describe(), "ricker(peak_frequency=4, delay=0.3, amplitude=1)");
  const ParticleSet<3> particles = buildParticles<3>(s.geometry);
  EXPECT_EQ(particles.size(), 9261);
  const std::vector<Probe> probes = resolveProbes(s.probes, particles);
  ASSERT_EQ(probes.size(), 2u);
  EXPECT_EQ(probes[0].particle, 10 + 10 * 21 + 10 * 441);  // (0.5, 0.5, 0.5)
  EXPECT_EQ(probes[1].particle, 10 + 10 * 21 + 16 * 441);  // (0.5, 0.5, 0.8)
  EXPECT_EQ(probes[1].component, 2);
  // Placed on the lattice alone (what a rank of a split run does), the same particles.
  const std::vector<Probe> onLattice = resolveProbesOnLattice(s.probes, s.geometry);
  ASSERT_EQ(onLattice.size(), 2u);
  EXPECT_EQ(onLattice[0].particle, probes[0].particle);
  EXPECT_EQ(onLattice[1].particle, probes[1].particle);
  // c_p = sqrt((lambda + 2 mu) / rho) = sqrt(3); dt <= cfl dx / c_p and divides end_time.
  const Real stable = s.geometry.spacing / std::sqrt(s.material.material().pWaveModulus() / s.material.density);
  EXPECT_EQ(s.integrator.stepsFor(stable), 104);
  EXPECT_DOUBLE_EQ(s.integrator.timeStepFor(stable), 1.5 / 104);
  EXPECT_TRUE(s.output.vtk && s.output.png);
}

TEST(SceneReader, LimitsOfTheLattice) {
  const SceneError tiny = sceneErrorOf([] {
    SceneReader r = loadScene(std::string(MFWAVE_SCENE_DATA_DIR) + "/block-ricker.toml", {"geometry.spacing=1e-300"});
    readFully(r);
  });
  EXPECT_EQ(tiny.key(), "geometry.spacing");
  EXPECT_NE(tiny.problem().find("would create more than 1e10 particles"), std::string::npos) << tiny.what();
}

TEST(SceneReader, ARunOfMoreThanATrillionStepsIsRefusedNamingTheKey) {
  // end_time = 1e300 used to overflow the step count into a huge step, refused as "above the limit".
  SceneReader reader = loadScene(std::string(MFWAVE_SCENE_DATA_DIR) + "/block-ricker.toml",
                                 {"integrator.end_time=1e300"});
  const Scene s = readFully(reader);
  try {
    s.integrator.stepsFor(0.01);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "integrator.end_time");
    EXPECT_NE(e.problem().find("more than 1e12 is refused"), std::string::npos) << e.what();
  }
  EXPECT_EQ(s.integrator.stepsFor(1e-12 * 1e300 / 0.5), 1000000000000L);  // 1e12 itself runs (cfl 0.5)
  const SceneError tiny = sceneErrorOf([] {
    SceneReader r = loadScene(sceneTestFile("valid/base-2d.toml"), {"integrator.time_step=1e-13"});
    readFully(r);
  });
  EXPECT_EQ(tiny.key(), "integrator.time_step");
  EXPECT_NE(tiny.problem().find("more than 1e12 is refused"), std::string::npos) << tiny.what();
}

TEST(SceneReader, TheBaseOfTheMalformedScenesIsValid) {
  SceneReader reader = loadScene(sceneTestFile("valid/base-2d.toml"));
  EXPECT_NO_THROW(readFully(reader));
}

TEST(SceneSchema, DescribeListsEveryKeyWithTypeUnitDefaultAndRange) {
  const SceneSchema schema = SceneSchema::common();
  const std::string text = schema.describe();
  EXPECT_NE(text.find("key"), std::string::npos);
  for (const auto& spec : schema.keys()) EXPECT_NE(text.find(spec.path), std::string::npos) << spec.path;
  // One line per key: find the spacing line and check its columns.
  const auto start = text.find("geometry.spacing");
  const std::string line = text.substr(start, text.find('\n', start) - start);
  for (const char* column : {"number", " m ", "required", "> 0", "must divide every side"})
    EXPECT_NE(line.find(column), std::string::npos) << column << " in: " << line;
  EXPECT_NE(text.find("line|rectangle|block"), std::string::npos);
  EXPECT_EQ(schema.childNames("boundary[]"),
            (std::vector<std::string>{"faces", "type", "traction", "value", "time_function"}));
  EXPECT_THROW(SceneSchema::common().add("geometry.spacing", ValueType::Number), std::logic_error);
}

TEST(SceneSchema, ExtraMethodNamesCanBeRegistered) {
  SceneSchema schema = SceneSchema::common();
  schema.addChoice("method.name", "very_weak_sph");
  std::string text = kMinimal;
  text.replace(text.find("finite_difference"), 17, "very_weak_sph");
  SceneReader reader = parseScene(text, "m.toml", {}, schema);
  EXPECT_EQ(readFully(reader).method.name, "very_weak_sph");
  SceneReader common = parseScene(text, "m.toml");
  EXPECT_EQ(sceneErrorOf([&] { readScene(common); }).key(), "method.name");
}

}  // namespace
}  // namespace mfwave
