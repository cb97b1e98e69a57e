// Every file in malformed/ is a scene with one mistake. Its first line names the key path the
// error must carry ("# expect-key: boundary[1].faces[1]"); an optional "# expect-text:" line
// gives a substring of the message. Each is read as a driver reads it (common sections, then
// the unknown-key check) and must fail with a SceneError at that key, whose message names the
// file and a line. The driver tests reuse these files: keep the convention.
//
// malformed/updated_lagrangian_sph/ holds scenes of the drivers that run the updated-Lagrangian SPH:
// they are read with that method's keys and the first-order integrators (as those drivers read
// them), and stay out of malformed/ itself, whose files every driver must reject at their key.

#include "SceneTestSupport.hpp"

#include "io/scene/LoadScene.hpp"
#include "io/scene/Scene.hpp"
#include "wiring/UpdatedLagrangianSphSpec.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <functional>
#include <gtest/gtest.h>

namespace mfwave {
namespace {

namespace fs = std::filesystem;

// True if `message` contains "<file>:<line>:" with a positive line number. (Plain string search:
// std::regex trips GCC 12's -Wmaybe-uninitialized under the sanitizers.)
bool namesFileAndLine(const std::string& message, const std::string& file) {
  for (auto at = message.find(file + ":"); at != std::string::npos; at = message.find(file + ":", at + 1)) {
    std::size_t digit = at + file.size() + 1;
    const std::size_t first = digit;
    while (digit < message.size() && std::isdigit(static_cast<unsigned char>(message[digit]))) ++digit;
    if (digit > first && message[first] != '0' && digit < message.size() && message[digit] == ':') return true;
  }
  return false;
}

const std::string updatedLagrangianSphFolder = "updated_lagrangian_sph";

std::vector<std::string> scenesIn(const std::string& folder) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder))
    if (entry.is_regular_file() && entry.path().extension() == ".toml")
      names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::vector<std::string> malformedScenes() { return scenesIn(MFWAVE_MALFORMED_SCENES_DIR); }

std::vector<std::string> malformedUpdatedLagrangianSphScenes() {
  return scenesIn(std::string(MFWAVE_MALFORMED_SCENES_DIR) + "/" + updatedLagrangianSphFolder);
}

struct Expectation {
  std::string key, text;
};

Expectation expectationOf(const std::string& path) {
  std::ifstream in(path);
  Expectation e;
  std::string line;
  for (int n = 0; n < 5 && std::getline(in, line); ++n) {
    const std::string keyTag = "# expect-key: ", textTag = "# expect-text: ";
    if (line.rfind(keyTag, 0) == 0) e.key = line.substr(keyTag.size());
    if (line.rfind(textTag, 0) == 0) e.text = line.substr(textTag.size());
  }
  return e;
}

// Reads the scene at `path` as a driver does (`read` after loading) and checks the SceneError
// against the file's expect lines.
void expectFailureAtTheExpectedKey(const std::string& path, const std::string& file,
                                   const std::function<void(SceneReader&)>& read,
                                   const SceneSchema& schema = SceneSchema::common()) {
  const Expectation expected = expectationOf(path);
  ASSERT_FALSE(expected.key.empty()) << file << " has no '# expect-key:' first line";
  const SceneError e = testing::sceneErrorOf([&] {
    SceneReader reader = loadScene(path, {}, schema);
    read(reader);
  });
  const std::string message = e.what();
  EXPECT_EQ(e.key(), expected.key) << message;
  // The file name and a line number: ".../NN-name.toml:12: key: problem" (":12:5:" for syntax).
  EXPECT_TRUE(namesFileAndLine(message, file)) << message;
  if (!expected.text.empty()) {
    EXPECT_NE(message.find(expected.text), std::string::npos) << message;
  }
}

std::string testNameOf(const ::testing::TestParamInfo<std::string>& file) {
  std::string name = file.param.substr(0, file.param.size() - 5);
  std::replace(name.begin(), name.end(), '-', '_');
  return "f" + name;
}

class MalformedScene : public ::testing::TestWithParam<std::string> {};

TEST_P(MalformedScene, FailsAtTheExpectedKey) {
  expectFailureAtTheExpectedKey(std::string(MFWAVE_MALFORMED_SCENES_DIR) + "/" + GetParam(), GetParam(),
                                [](SceneReader& reader) { testing::readFully(reader); });
}

INSTANTIATE_TEST_SUITE_P(Files, MalformedScene, ::testing::ValuesIn(malformedScenes()), testNameOf);

TEST(MalformedScenes, AtLeastThirtyCases) { EXPECT_GE(malformedScenes().size(), 30u); }

// The scenes of the updated-Lagrangian SPH drivers: common sections, the method's options, the
// first-order integrator, then the unknown-key check.
class MalformedUpdatedLagrangianSphScene : public ::testing::TestWithParam<std::string> {};

TEST_P(MalformedUpdatedLagrangianSphScene, FailsAtTheExpectedKey) {
  SceneSchema schema = SceneSchema::common();
  addUpdatedLagrangianSphKeys(schema);
  useFirstOrderIntegrators(schema);
  const std::string path =
      std::string(MFWAVE_MALFORMED_SCENES_DIR) + "/" + updatedLagrangianSphFolder + "/" + GetParam();
  expectFailureAtTheExpectedKey(
      path, GetParam(),
      [](SceneReader& reader) {
        const Scene scene = readScene(reader);
        if (scene.method.name == "updated_lagrangian_sph") readUpdatedLagrangianSph(reader, scene.material.material());
        readFirstOrderIntegrator(reader);
        reader.checkAllKeysRead();
      },
      schema);
}

INSTANTIATE_TEST_SUITE_P(Files, MalformedUpdatedLagrangianSphScene,
                         ::testing::ValuesIn(malformedUpdatedLagrangianSphScenes()), testNameOf);

TEST(MalformedScenes, UpdatedLagrangianSphCasesArePresent) {
  EXPECT_GE(malformedUpdatedLagrangianSphScenes().size(), 4u);
}

}  // namespace
}  // namespace mfwave
