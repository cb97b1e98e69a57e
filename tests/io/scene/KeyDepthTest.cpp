// io/scene/KeyDepth: a dotted key deeper than kMaxKeyParts is refused as a syntax error naming where
// it starts, in a scene file and in --set, before the TOML reader sees it (a 200,000-part key used
// to kill every driver with SIGSEGV inside the reader); values, strings and comments full of dots
// pass.

#include "io/scene/KeyDepth.hpp"
#include "io/scene/LoadScene.hpp"
#include "SceneTestSupport.hpp"

#include <gtest/gtest.h>

#include <string>

namespace mfwave {
namespace {

using testing::sceneErrorOf;
using testing::sceneTestFile;

std::string dottedKey(std::size_t parts) {
  std::string key = "a";
  for (std::size_t k = 1; k < parts; ++k) key += ".a";
  return key;
}

TEST(KeyDepth, ADeepDottedKeyIsRefusedWhereItStarts) {
  const SceneError e = sceneErrorOf([] { parseScene(dottedKey(200000) + " = 1\n", "deep.toml", {}, SceneSchema::common()); });
  EXPECT_EQ(e.key(), "(syntax)");
  EXPECT_EQ(e.location(), "deep.toml:1:1");
  EXPECT_NE(e.problem().find("more than 64 parts"), std::string::npos) << e.what();

  // In a table header, quoted, with spaces around the dots, on a later line, in an inline table.
  const std::string header = "# a comment\n[" + dottedKey(65) + "]\n";
  EXPECT_EQ(sceneErrorOf([&] { checkKeyDepth(header, "s.toml"); }).location(), "s.toml:2:2");
  std::string quoted = "x = 1\n  \"q\"";
  for (int k = 0; k < 70; ++k) quoted += " . 'q'";
  EXPECT_EQ(sceneErrorOf([&] { checkKeyDepth(quoted + " = 2\n", "s.toml"); }).location(), "s.toml:2:3");
  EXPECT_EQ(sceneErrorOf([&] { checkKeyDepth("t = { " + dottedKey(100) + " = 1 }", "s.toml"); }).location(),
            "s.toml:1:7");
}

TEST(KeyDepth, KeysUpToTheLimitAndDotsInValuesStringsAndCommentsPass) {
  checkKeyDepth(dottedKey(64) + " = 1\n", "s.toml");
  std::string floats = "a = [";
  for (int k = 0; k < 1000; ++k) floats += "1.5, 2.5e-3, ";
  checkKeyDepth(floats + "0.0]\n", "s.toml");
  const std::string dots(5000, '.');
  checkKeyDepth("s = \"" + dots + "\"\nl = '" + dots + "'\n# " + dots + "\n", "s.toml");
  checkKeyDepth("m = \"\"\"\n" + dottedKey(500) + "\n\"\"\"\nn = '''" + dottedKey(500) + "'''\n", "s.toml");
  checkKeyDepth("e = \"a\\\"" + dottedKey(500) + "\"\n", "s.toml");  // an escaped quote stays inside
  checkKeyDepth("d = 1979-05-27T07:32:00.999999-07:00\n", "s.toml");
}

TEST(KeyDepth, NestedValuesStopAtTheReadersLimit) {
  const std::string deep = "a = " + std::string(100000, '[') + std::string(100000, ']') + "\n";
  const SceneError e = sceneErrorOf([&] { parseScene(deep, "nested.toml", {}, SceneSchema::common()); });
  EXPECT_EQ(e.key(), "(syntax)");
  EXPECT_NE(e.problem().find("maximum nested value depth of 256"), std::string::npos) << e.what();
}

TEST(KeyDepth, ADeepOverrideIsRefused) {
  const SceneError path = sceneErrorOf([] { loadScene(sceneTestFile("valid/full-3d.toml"), {dottedKey(100000) + "=1"}); });
  EXPECT_EQ(path.key(), "--set");
  EXPECT_NE(path.problem().find("100000 parts"), std::string::npos) << path.what();
  EXPECT_LT(path.problem().size(), 400u);  // the assignment is quoted shortened
  const SceneError value =
      sceneErrorOf([] { loadScene(sceneTestFile("valid/full-3d.toml"), {"output.x={ " + dottedKey(100000) + " = 1 }"}); });
  EXPECT_EQ(value.key(), "--set");
  EXPECT_NE(value.problem().find("more than 64 parts"), std::string::npos) << value.what();
}

}  // namespace
}  // namespace mfwave
