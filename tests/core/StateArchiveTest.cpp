// The named arrays a checkpoint holds (core/StateArchive): sections share one storage, sizes and
// missing names are refused naming the array, text and whole numbers round-trip.

#include "core/Error.hpp"
#include "core/StateArchive.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace mfwave {
namespace {

TEST(StateArchive, SectionsPrefixTheirNamesAndShareTheStorage) {
  StateArchive archive;
  StateArchive integrator = archive.section("integrator");
  Vector u(3);
  u << 1.5, -2.0, 1e-300;
  integrator.put("u", u);
  integrator.section("history").putScalar("steps", 42);
  archive.putText("note", "growth at step 7\n\xff");
  ASSERT_EQ(archive.arrays().size(), 3u);
  EXPECT_EQ(archive.arrays()[0].first, "integrator.u");
  EXPECT_EQ(archive.arrays()[1].first, "integrator.history.steps");

  const StateArchive copy(archive.arrays());  // as a checkpoint file gives it back
  Vector back(3);
  copy.section("integrator").get("u", back);
  EXPECT_EQ(back, u);
  EXPECT_EQ(copy.section("integrator").section("history").integer("steps"), 42);
  EXPECT_EQ(copy.text("note"), "growth at step 7\n\xff");
  EXPECT_TRUE(copy.has("integrator.u"));
  EXPECT_FALSE(copy.section("integrator").has("v"));
}

TEST(StateArchive, MissingOrMisSizedArraysAreRefusedNamingThem) {
  StateArchive archive;
  archive.put("u", std::vector<Real>{1, 2});
  archive.putScalar("half", 0.5);
  Vector three(3);
  const auto expectRefusal = [](const std::function<void()>& read, const std::string& name) {
    try {
      read();
      FAIL() << "read " << name;
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), "--restart");
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  };
  expectRefusal([&] { archive.get("u", three); }, "'u' holds 2 values where this run has 3");
  expectRefusal([&] { (void)archive.section("observer0").get("times"); }, "observer0.times");
  expectRefusal([&] { (void)archive.scalar("u"); }, "'u' holds 2 values, not one");
  expectRefusal([&] { (void)archive.integer("half"); }, "not a whole number");
  Vector resized;
  archive.getResized("u", resized);
  EXPECT_EQ(resized.size(), 2);
  archive.put("u", std::vector<Real>{7});  // put again: replaced, not appended
  EXPECT_EQ(archive.arrays().size(), 2u);
  EXPECT_EQ(archive.scalar("u"), 7);
}

}  // namespace
}  // namespace mfwave
