// Ghost layers: counts per chosen faces, kinds and ordering, lattice positions, and that a
// kernel support around edge and corner particles is complete.

#include "support/InputErrorKey.hpp"
#include "core/Error.hpp"
#include "particles/BoxFace.hpp"
#include "particles/GhostLayers.hpp"
#include "particles/Lattice.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <tuple>

using namespace mfwave;

namespace {

const Vec3 kLower(0, 0, 0);
const Vec3 kUpper(7, 7, 7);
constexpr Real kDx = 0.5;

using Offset = std::tuple<long, long, long>;

// Integer lattice offsets (in units of dx) of all particles of `set` within distance
// radius*dx of particle `centre`.
std::set<Offset> offsetsWithin(const ParticleSet<3>& set, Index centre, Real radius) {
  std::set<Offset> found;
  const Vec3 c = set.position(centre);
  for (Index j = 0; j < set.size(); ++j) {
    const Vec3 k = (set.position(j) - c) / kDx;
    if (k.norm() <= radius + 1e-12) {
      found.emplace(std::lround(k[0]), std::lround(k[1]), std::lround(k[2]));
    }
  }
  return found;
}

// All integer vectors with |k| <= radius: the support as an unbounded lattice would fill it.
std::set<Offset> fullBall(Real radius) {
  std::set<Offset> ball;
  const long r = static_cast<long>(std::ceil(radius));
  for (long x = -r; x <= r; ++x)
    for (long y = -r; y <= r; ++y)
      for (long z = -r; z <= r; ++z)
        if (x * x + y * y + z * z <= radius * radius) ball.emplace(x, y, z);
  return ball;
}

}  // namespace

TEST(GhostLayers, TwoLayersOnAllFacesFillTheGrownBlock) {
  ParticleSet<3> set = makeBlock(kLower, kUpper, kDx);
  const Index added = addGhostLayers<3>(set, kLower, kUpper, kDx, 2, allFaces(3));
  EXPECT_EQ(added, 19 * 19 * 19 - 15 * 15 * 15);
  EXPECT_EQ(ghostLayerCount<3>(kLower, kUpper, kDx, 2, allFaces(3)), added);  // counted without building
  ASSERT_EQ(set.size(), 19 * 19 * 19);
  EXPECT_EQ(set.physicalCount(), 3375);
  EXPECT_EQ(set.ghostCount(), added);

  std::set<Index> ids(set.globalId.begin(), set.globalId.end());
  EXPECT_EQ(static_cast<Index>(ids.size()), set.size());  // ids stay unique
  EXPECT_EQ(*ids.rbegin(), set.size() - 1);

  std::set<Offset> points;
  for (Index i = 0; i < set.size(); ++i) {
    const auto s = static_cast<std::size_t>(i);
    const bool ghost = i >= set.physicalCount();
    ASSERT_EQ(set.kind[s], ghost ? ParticleKind::Ghost : ParticleKind::Physical) << i;
    const Vec3 k = set.position(i) / kDx;
    ASSERT_EQ((k - k.array().round().matrix()).norm(), 0) << "ghost off the lattice: " << i;
    ASSERT_TRUE(k.minCoeff() >= -2 && k.maxCoeff() <= 16) << i;
    if (ghost) {
      EXPECT_EQ(set.faceMask[s], 0);
      EXPECT_EQ(set.volume[s], 0.125);
      EXPECT_TRUE(k.minCoeff() < 0 || k.maxCoeff() > 14) << "ghost inside the box: " << i;
    }
    points.emplace(std::lround(k[0]), std::lround(k[1]), std::lround(k[2]));
  }
  EXPECT_EQ(static_cast<Index>(points.size()), set.size());  // no point twice
}

TEST(GhostLayers, OneFaceOnly) {
  ParticleSet<3> set = makeBlock(kLower, kUpper, kDx);
  const Index added = addGhostLayers<3>(set, kLower, kUpper, kDx, 2, faceBit(BoxFace::PlusZ));
  EXPECT_EQ(added, 2 * 15 * 15);
  for (Index i = set.physicalCount(); i < set.size(); ++i) {
    const Real z = set.position(i)[2];
    ASSERT_TRUE(z == 7.5 || z == 8.0) << z;
  }
}

TEST(GhostLayers, KernelSupportAroundCornersIsComplete) {
  ParticleSet<3> set = makeBlock(kLower, kUpper, kDx);
  addGhostLayers<3>(set, kLower, kUpper, kDx, 2, allFaces(3));
  const std::set<Offset> ball = fullBall(2);
  ASSERT_EQ(ball.size(), 33u);
  EXPECT_EQ(offsetsWithin(set, 0, 2), ball);     // corner (0,0,0)
  EXPECT_EQ(offsetsWithin(set, 3374, 2), ball);  // corner (7,7,7)
  EXPECT_EQ(offsetsWithin(set, 14, 2), ball);    // corner (7,0,0)
}

TEST(GhostLayers, EdgeBetweenTwoChosenFacesIsCompleteOthersAreNot) {
  ParticleSet<3> set = makeBlock(kLower, kUpper, kDx);
  addGhostLayers<3>(set, kLower, kUpper, kDx, 2, faceBit(BoxFace::MinusX) | faceBit(BoxFace::MinusY));
  EXPECT_EQ(set.ghostCount(), 17 * 17 * 15 - 15 * 15 * 15);
  EXPECT_EQ(ghostLayerCount<3>(kLower, kUpper, kDx, 2, faceBit(BoxFace::MinusX) | faceBit(BoxFace::MinusY)),
            set.ghostCount());
  EXPECT_EQ(ghostLayerCount<3>(kLower, kUpper, kDx, 0, allFaces(3)), 0);
  EXPECT_THROW(ghostLayerCount<3>(kLower, kUpper, kDx, -1, allFaces(3)), InputError);
  const std::set<Offset> ball = fullBall(2);
  const Index edgeMiddle = 7 * 15 * 15;  // (0, 0, 3.5): on the -x/-y edge
  ASSERT_EQ(set.position(edgeMiddle), Vec3(0, 0, 3.5));
  EXPECT_EQ(offsetsWithin(set, edgeMiddle, 2), ball);
  // The corner (0,0,0) also needs the -z side, which was not chosen: the 10 offsets with
  // k_z < 0 are missing.
  EXPECT_EQ(offsetsWithin(set, 0, 2).size(), 33u - 10u);
}

TEST(GhostLayers, LineAndRectangle) {
  ParticleSet<1> line = makeLine(0, 1, 0.25);
  EXPECT_EQ(addGhostLayers<1>(line, Vec1(0), Vec1(1), 0.25, 3, faceBit(BoxFace::PlusX)), 3);
  EXPECT_EQ(line.position(line.size() - 1)[0], 1.75);

  ParticleSet<2> rect = makeRectangle(Vec2(0, 0), Vec2(2, 1), 0.25);
  EXPECT_EQ(addGhostLayers<2>(rect, Vec2(0, 0), Vec2(2, 1), 0.25, 1, allFaces(2)), 11 * 7 - 9 * 5);
  EXPECT_EQ(rect.position(rect.physicalCount()), Vec2(-0.25, -0.25));  // first ghost: a corner
}

TEST(GhostLayers, ZeroLayersAddNothing) {
  ParticleSet<2> rect = makeRectangle(Vec2(0, 0), Vec2(1, 1), 0.5);
  EXPECT_EQ(addGhostLayers<2>(rect, Vec2(0, 0), Vec2(1, 1), 0.5, 0, allFaces(2)), 0);
  EXPECT_EQ(rect.size(), 9);
}

TEST(GhostLayers, BadInputIsRejected) {
  ParticleSet<2> rect = makeRectangle(Vec2(0, 0), Vec2(1, 1), 0.5);
  EXPECT_EQ(mfwave::testing::inputErrorKey([&] { addGhostLayers<2>(rect, Vec2(0, 0), Vec2(1, 1), 0.5, -1, allFaces(2)); }),
            "ghost_layers");
  EXPECT_EQ(mfwave::testing::inputErrorKey([&] { addGhostLayers<2>(rect, Vec2(0, 0), Vec2(1, 1), 0.5, 1, faceBit(BoxFace::PlusZ)); }),
            "ghost_faces");
  EXPECT_EQ(mfwave::testing::inputErrorKey([&] { addGhostLayers<2>(rect, Vec2(0, 0), Vec2(1, 1), 0.3, 1, allFaces(2)); }),
            "spacing");
  EXPECT_EQ(rect.size(), 9);
}
