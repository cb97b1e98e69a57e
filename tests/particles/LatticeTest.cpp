// Lattice generators: counts, end nodes, face tags, outward normals and input errors.

#include "core/Error.hpp"
#include "particles/BoxFace.hpp"
#include "particles/Lattice.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <string>

using namespace mfwave;

namespace {

// The InputError key thrown by f, or "" when f throws nothing; the message goes to `message`.
template <class F>
std::string errorKey(F&& f, std::string* message = nullptr) {
  try {
    f();
  } catch (const InputError& e) {
    if (message) *message = e.what();
    return e.key();
  }
  return "";
}

// Histogram of facetCount over a set: [interior, face, edge, corner].
template <int D>
std::array<Index, 4> facetHistogram(const ParticleSet<D>& set) {
  std::array<Index, 4> h{};
  for (Index i = 0; i < set.size(); ++i) ++h[static_cast<std::size_t>(set.facetCount(i))];
  return h;
}

}  // namespace

TEST(Lattice, LineCountsEndsAndTags) {
  const ParticleSet<1> line = makeLine(-1, 1, 0.125);
  ASSERT_EQ(line.size(), 17);
  EXPECT_EQ(line.physicalCount(), 17);
  EXPECT_EQ(line.position(0)[0], -1);
  EXPECT_EQ(line.position(1)[0], -0.875);
  EXPECT_EQ(line.position(16)[0], 1);
  EXPECT_EQ(line.faceMask[0], faceBit(BoxFace::MinusX));
  EXPECT_EQ(line.faceMask[16], faceBit(BoxFace::PlusX));
  EXPECT_EQ(line.outwardNormal(0), Vec1(-1));
  EXPECT_EQ(line.volume[5], 0.125);
  EXPECT_EQ((facetHistogram<1>(line)), (std::array<Index, 4>{15, 2, 0, 0}));
}

TEST(Lattice, SpacingThatDividesOnlyUpToRoundingIsAccepted) {
  const ParticleSet<1> line = makeLine(0, 1, 0.1);  // 1 / 0.1 is not exactly 10 in binary
  ASSERT_EQ(line.size(), 11);
  EXPECT_EQ(line.position(10)[0], 1.0);  // the far end is hit exactly
  EXPECT_NEAR(line.position(3)[0], 0.3, 1e-15);
}

TEST(Lattice, RectangleCountsEndsAndTags) {
  const ParticleSet<2> rect = makeRectangle(Vec2(0, -1), Vec2(2, 0.5), 0.25);
  ASSERT_EQ(rect.size(), 9 * 7);
  EXPECT_EQ(rect.position(0), Vec2(0, -1));
  EXPECT_EQ(rect.position(1), Vec2(0.25, -1));  // x varies fastest
  EXPECT_EQ(rect.position(9), Vec2(0, -0.75));
  EXPECT_EQ(rect.position(62), Vec2(2, 0.5));
  EXPECT_EQ((facetHistogram<2>(rect)), (std::array<Index, 4>{7 * 5, 2 * 7 + 2 * 5, 4, 0}));
  EXPECT_DOUBLE_EQ(rect.volume[0], 0.0625);
  EXPECT_NEAR((rect.outwardNormal(62) - Vec2(1, 1) / std::sqrt(2.0)).norm(), 0, 1e-15);
}

TEST(Lattice, BlockCountsAndFaceEdgeCornerTags) {
  const ParticleSet<3> block = makeBlock(Vec3(0, 0, 0), Vec3(7, 7, 7), 0.5);
  ASSERT_EQ(block.size(), 3375);
  EXPECT_EQ(block.position(0), Vec3(0, 0, 0));
  EXPECT_EQ(block.position(1), Vec3(0.5, 0, 0));
  EXPECT_EQ(block.position(3374), Vec3(7, 7, 7));
  EXPECT_EQ(block.globalId[3374], 3374);
  EXPECT_EQ(block.volume[100], 0.125);
  EXPECT_EQ((facetHistogram<3>(block)), (std::array<Index, 4>{13 * 13 * 13, 6 * 13 * 13, 12 * 13, 8}));
  for (int face = 0; face < 6; ++face) {
    Index onFace = 0;
    for (Index i = 0; i < block.size(); ++i) onFace += (block.faceMask[static_cast<std::size_t>(i)] >> face) & 1;
    EXPECT_EQ(onFace, 15 * 15) << "face " << face;
  }
}

TEST(Lattice, BlockOffsetFromOriginWithUnequalSides) {
  const ParticleSet<3> block = makeBlock(Vec3(-1, 0, 2), Vec3(1, 0.5, 3), 0.25);
  ASSERT_EQ(block.size(), 9 * 3 * 5);
  EXPECT_EQ(block.position(0), Vec3(-1, 0, 2));
  EXPECT_EQ(block.position(block.size() - 1), Vec3(1, 0.5, 3));
  EXPECT_EQ((facetHistogram<3>(block)), (std::array<Index, 4>{7 * 1 * 3, 2 * (7 * 1 + 7 * 3 + 1 * 3),
                                                               4 * (7 + 1 + 3), 8}));
}

TEST(Lattice, OutwardNormalsAtCornersEdgesAndFaces) {
  const ParticleSet<3> block = makeBlock(Vec3(0, 0, 0), Vec3(7, 7, 7), 0.5);
  Index corners = 0;
  for (Index i = 0; i < block.size(); ++i) {
    const Vec3 x = block.position(i);
    Vec3 expected = Vec3::Zero();
    for (int a = 0; a < 3; ++a) expected[a] = x[a] == 0 ? -1 : (x[a] == 7 ? 1 : 0);
    const int facets = block.facetCount(i);
    ASSERT_EQ(facets, static_cast<int>(expected.cwiseAbs().sum())) << "particle " << i;
    if (facets > 0) expected /= std::sqrt(static_cast<Real>(facets));
    ASSERT_NEAR((block.outwardNormal(i) - expected).norm(), 0, 1e-15) << "particle " << i;
    const auto normals = block.facetNormals(i);
    ASSERT_EQ(static_cast<int>(normals.size()), facets);
    Vec3 sum = Vec3::Zero();
    for (const Vec3& n : normals) {
      EXPECT_EQ(n.norm(), 1);
      EXPECT_EQ(n.cwiseAbs().sum(), 1);  // axis-aligned
      sum += n;
    }
    if (facets == 3) {
      ++corners;
      EXPECT_NEAR(std::abs(block.outwardNormal(i)[0]), 1 / std::sqrt(3.0), 1e-15);
      EXPECT_EQ(sum.cwiseAbs(), Vec3(1, 1, 1));
    }
  }
  EXPECT_EQ(corners, 8);
}

TEST(Lattice, BadSpacingIsAnInputError) {
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  const Real inf = std::numeric_limits<Real>::infinity();
  EXPECT_EQ(errorKey([] { makeLine(0, 1, 0); }), "spacing");
  EXPECT_EQ(errorKey([] { makeLine(0, 1, -0.1); }), "spacing");
  EXPECT_EQ(errorKey([nan] { makeLine(0, 1, nan); }), "spacing");
  EXPECT_EQ(errorKey([inf] { makeRectangle(Vec2(0, 0), Vec2(1, 1), inf); }), "spacing");
  EXPECT_EQ(errorKey([] { makeLine(0, 1, 3); }), "spacing");  // larger than the length
}

TEST(Lattice, SpacingThatDoesNotDivideNamesTheAxis) {
  std::string message;
  EXPECT_EQ(errorKey([] { makeBlock(Vec3(0, 0, 0), Vec3(1, 0.9, 1), 0.2); }, &message), "spacing");
  EXPECT_NE(message.find("does not divide the length"), std::string::npos) << message;
  EXPECT_NE(message.find("axis y"), std::string::npos) << message;
  EXPECT_EQ(errorKey([] { makeLine(0, 1, 0.3); }), "spacing");
}

TEST(Lattice, InvertedOrEmptyBoxIsAGeometryError) {
  std::string message;
  EXPECT_EQ(errorKey([] { makeRectangle(Vec2(0, 1), Vec2(1, 0), 0.1); }, &message), "geometry");
  EXPECT_NE(message.find("axis y"), std::string::npos) << message;
  EXPECT_EQ(errorKey([] { makeLine(1, 1, 0.1); }), "geometry");
  EXPECT_EQ(errorKey([] { makeBlock(Vec3(0, 0, 2), Vec3(1, 1, 1), 0.5); }, &message), "geometry");
  EXPECT_NE(message.find("axis z"), std::string::npos) << message;
}

// A rank's block of the lattice: the particles of the whole lattice's nodes in the block, in their
// order, with the same positions (bit for bit), face tags and global ids.
TEST(Lattice, ABlockHasTheWholeLatticesParticles) {
  const Vec3 lower(-0.3, 0.1, 2.0), upper(0.7, 0.9, 2.6);
  const Real dx = 0.1;
  const ParticleSet<3> whole = makeLattice<3>(lower, upper, dx);  // 11 x 9 x 7
  const std::array<Index, 3> first{3, 0, 2}, end{11, 5, 6};
  const ParticleSet<3> block = makeLattice<3>(lower, upper, dx, first, end);
  ASSERT_EQ(block.size(), 8 * 5 * 4);
  Index k = 0;
  for (Index z = first[2]; z < end[2]; ++z)
    for (Index y = first[1]; y < end[1]; ++y)
      for (Index x = first[0]; x < end[0]; ++x, ++k) {
        const Index p = x + 11 * (y + 9 * z);
        for (int a = 0; a < 3; ++a) EXPECT_EQ(block.position(k)[a], whole.position(p)[a]) << k;
        EXPECT_EQ(block.faceMask[static_cast<std::size_t>(k)], whole.faceMask[static_cast<std::size_t>(p)]) << k;
        EXPECT_EQ(block.globalId[static_cast<std::size_t>(k)], p);
      }
  EXPECT_EQ(errorKey([&] { makeLattice<3>(lower, upper, dx, {0, 0, 0}, {12, 9, 7}); }), "lattice");
  EXPECT_EQ(errorKey([&] { makeLattice<3>(lower, upper, dx, {4, 0, 0}, {4, 9, 7}); }), "lattice");
}

// The nearest node by lattice arithmetic is the one a search over the particles finds (the first
// of equally near ones), for points inside, on and between nodes, at ties and beyond the box.
TEST(Lattice, TheNearestNodeIsTheOneASearchFinds) {
  const Vec2 lower(-0.3, 0.1), upper(0.7, 0.9);
  const Real dx = 0.1;
  const ParticleSet<2> whole = makeLattice<2>(lower, upper, dx);
  auto search = [&](const Vec2& x) {
    Index best = 0;
    Real distance = std::numeric_limits<Real>::infinity();
    for (Index p = 0; p < whole.size(); ++p)
      if ((whole.position(p) - x).squaredNorm() < distance) {
        distance = (whole.position(p) - x).squaredNorm();
        best = p;
      }
    return best;
  };
  int checked = 0;
  for (Real x = -0.45; x <= 0.85; x += 0.0125)
    for (Real y = -0.05; y <= 1.05; y += 0.025) {
      const Vec2 point(x, y);
      EXPECT_EQ(nearestLatticeNode<2>(lower, upper, dx, point), search(point)) << x << ", " << y;
      ++checked;
    }
  // Exactly halfway between two nodes' coordinates: the lower one.
  const Vec2 half(0.5 * (whole.position(3)[0] + whole.position(4)[0]), whole.position(0)[1]);
  EXPECT_EQ(nearestLatticeNode<2>(lower, upper, dx, half), search(half));
  EXPECT_GT(checked, 4000);
}
