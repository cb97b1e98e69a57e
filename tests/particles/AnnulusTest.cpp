// Annulus generator: exact total volume, particles inside the ring, even nearest-neighbour
// spacing, input errors; appendParticles joining two rings into one set.

#include "core/Error.hpp"
#include "particles/Annulus.hpp"
#include "particles/Lattice.hpp"
#include "support/InputErrorKey.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <string>

using namespace mfwave;

namespace {

constexpr double pi = mfwave::kPi;

struct Ring {
  double inner, outer, spacing;
};

// The GMS rings (r = 3, R = 4 in units of 1 cm, 10 rings), a width that is not a whole number of
// spacings, a thin ring of one circle, and a disc.
const Ring rings[] = {{0.03, 0.04, 0.001}, {1.0, 1.55, 0.1}, {2.0, 2.1, 0.1}, {0.0, 1.0, 0.1}};

double nearestNeighbourDistance(const ParticleSet<2>& set, Index i) {
  double best = std::numeric_limits<double>::infinity();
  for (Index j = 0; j < set.size(); ++j)
    if (j != i) best = std::min(best, (set.position(i) - set.position(j)).norm());
  return best;
}

}  // namespace

TEST(Annulus, TotalVolumeIsTheAreaOfTheRing) {
  for (const Ring& g : rings) {
    const ParticleSet<2> set = makeAnnulus(Vec2(0.5, -0.25), g.inner, g.outer, g.spacing);
    const double total = std::accumulate(set.volume.begin(), set.volume.end(), 0.0);
    const double area = pi * (g.outer * g.outer - g.inner * g.inner);
    EXPECT_NEAR(total, area, 1e-12 * area) << "r = " << g.inner << ", R = " << g.outer;
    // Each particle's share is close to spacing^2 (dr and the arc length are both ~ spacing).
    for (const double v : set.volume) {
      EXPECT_GT(v, 0.7 * g.spacing * g.spacing);
      EXPECT_LT(v, 1.4 * g.spacing * g.spacing);
    }
    EXPECT_EQ(set.physicalCount(), set.size());
  }
}

TEST(Annulus, ParticlesLieInsideTheRingHalfARingWidthFromItsEdges) {
  for (const Ring& g : rings) {
    const Vec2 centre(0.5, -0.25);
    const ParticleSet<2> set = makeAnnulus(centre, g.inner, g.outer, g.spacing);
    const double rings = std::max(1.0, std::round((g.outer - g.inner) / g.spacing));
    const double halfWidth = 0.5 * (g.outer - g.inner) / rings;
    for (Index i = 0; i < set.size(); ++i) {
      const double r = (set.position(i) - centre).norm();
      EXPECT_GE(r, g.inner + halfWidth * (1 - 1e-12));
      EXPECT_LE(r, g.outer - halfWidth * (1 - 1e-12));
      EXPECT_EQ(set.faceMask[static_cast<std::size_t>(i)], 0);
    }
  }
}

TEST(Annulus, NearestNeighboursAreAboutOneSpacingAway) {
  for (const Ring& g : rings) {
    const ParticleSet<2> set = makeAnnulus(Vec2(0, 0), g.inner, g.outer, g.spacing);
    double smallest = std::numeric_limits<double>::infinity(), largest = 0;
    for (Index i = 0; i < set.size(); ++i) {
      const double d = nearestNeighbourDistance(set, i);
      smallest = std::min(smallest, d);
      largest = std::max(largest, d);
    }
    EXPECT_GE(smallest, 0.8 * g.spacing) << "r = " << g.inner << ", R = " << g.outer;
    EXPECT_LE(largest, 1.2 * g.spacing) << "r = " << g.inner << ", R = " << g.outer;
  }
}

TEST(Annulus, GmsRingHasTenCirclesOfTheExpectedCounts) {
  const ParticleSet<2> set = makeAnnulus(Vec2(0, 0), 0.03, 0.04, 0.001);
  // Circle k at r_k = 0.03 + (k + 1/2) 0.001 holds round(2 pi r_k / 0.001) particles.
  Index expected = 0;
  for (int k = 0; k < 10; ++k) expected += std::llround(2 * pi * (0.03 + (k + 0.5) * 0.001) / 0.001);
  EXPECT_EQ(set.size(), expected);
  EXPECT_EQ(set.globalId.front(), 0);
  EXPECT_EQ(set.globalId.back(), expected - 1);
}

TEST(Annulus, RejectsBadInputNamingTheKey) {
  const Vec2 c(0, 0);
  EXPECT_EQ(mfwave::testing::inputErrorKey([&] { makeAnnulus(c, -0.1, 1, 0.1); }), "inner_radius");
  EXPECT_EQ(mfwave::testing::inputErrorKey([&] { makeAnnulus(c, std::nan(""), 1, 0.1); }), "inner_radius");
  EXPECT_EQ(mfwave::testing::inputErrorKey([&] { makeAnnulus(c, 1, 1, 0.1); }), "outer_radius");
  EXPECT_EQ(mfwave::testing::inputErrorKey([&] { makeAnnulus(c, 1, 0.5, 0.1); }), "outer_radius");
  EXPECT_EQ(mfwave::testing::inputErrorKey([&] { makeAnnulus(c, 0.5, std::numeric_limits<double>::infinity(), 0.1); }), "outer_radius");
  EXPECT_EQ(mfwave::testing::inputErrorKey([&] { makeAnnulus(c, 0.5, 1, 0); }), "spacing");
  EXPECT_EQ(mfwave::testing::inputErrorKey([&] { makeAnnulus(c, 0.5, 1, -0.1); }), "spacing");
  EXPECT_EQ(mfwave::testing::inputErrorKey([&] { makeAnnulus(Vec2(std::nan(""), 0), 0.5, 1, 0.1); }), "centre");
}

TEST(AppendParticles, TwoRingsMakeOneSetWithFreshIds) {
  ParticleSet<2> both = makeAnnulus(Vec2(-0.05, 0), 0.03, 0.04, 0.002);
  const ParticleSet<2> right = makeAnnulus(Vec2(0.05, 0), 0.03, 0.04, 0.002);
  const Index left = both.size();
  appendParticles(both, right);
  ASSERT_EQ(both.size(), left + right.size());
  EXPECT_EQ(both.physicalCount(), both.size());
  for (Index i = 0; i < both.size(); ++i) EXPECT_EQ(both.globalId[static_cast<std::size_t>(i)], i);
  for (Index i = 0; i < right.size(); ++i) {
    EXPECT_EQ(both.position(left + i), right.position(i));
    EXPECT_EQ(both.volume[static_cast<std::size_t>(left + i)], right.volume[static_cast<std::size_t>(i)]);
  }
}

TEST(AppendParticles, KeepsKindsAndFaceMasksAndTheGhostOrder) {
  ParticleSet<1> into = makeLine(0, 1, 0.5);
  ParticleSet<1> ghosts;
  ghosts.add(Vec1(2), 0.5, ParticleKind::Ghost);
  appendParticles(into, makeLine(3, 4, 1));
  EXPECT_EQ(into.faceMask.back(), makeLine(3, 4, 1).faceMask.back());
  appendParticles(into, ghosts);
  EXPECT_EQ(into.ghostCount(), 1);
  EXPECT_THROW(appendParticles(into, makeLine(5, 6, 1)), Error);  // physical after a ghost
}
