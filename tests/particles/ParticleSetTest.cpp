// ParticleSet: storage round trips, the physical-before-ghost invariant, facet geometry.

#include "core/Error.hpp"
#include "particles/BoxFace.hpp"
#include "particles/ParticleSet.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfwave;

TEST(ParticleSet, AddStoresStructureOfArrays) {
  ParticleSet<2> set;
  EXPECT_EQ(set.add(Vec2(1, 2), 0.5), 0);
  EXPECT_EQ(set.add(Vec2(3, 4), 0.25, ParticleKind::Physical, faceBit(BoxFace::PlusY)), 1);
  EXPECT_EQ(set.add(Vec2(5, 6), 0.125, ParticleKind::Ghost, 0, 40), 2);
  ASSERT_EQ(set.size(), 3);
  EXPECT_EQ(set.physicalCount(), 2);
  EXPECT_EQ(set.ghostCount(), 1);
  EXPECT_EQ(set.coordinate(0), (std::vector<Real>{1, 3, 5}));
  EXPECT_EQ(set.coordinate(1), (std::vector<Real>{2, 4, 6}));
  EXPECT_EQ(set.globalId, (std::vector<Index>{0, 1, 40}));
  EXPECT_EQ(set.nextGlobalId(), 41);
  EXPECT_EQ(set.volume[1], 0.25);
  EXPECT_EQ(set.kind[2], ParticleKind::Ghost);
  EXPECT_EQ(set.faceMask[1], faceBit(BoxFace::PlusY));

  set.setPosition(1, Vec2(-7, 8));
  EXPECT_EQ(set.position(1), Vec2(-7, 8));
  EXPECT_EQ(set.coordinate(0)[1], -7);
}

TEST(ParticleSet, PhysicalParticleAfterGhostIsRejected) {
  ParticleSet<1> set;
  set.add(Vec1(0), 1, ParticleKind::Ghost);
  EXPECT_THROW(set.add(Vec1(1), 1, ParticleKind::Physical), Error);
  EXPECT_EQ(set.size(), 1);
  EXPECT_EQ(set.physicalCount(), 0);
}

TEST(ParticleSet, FacetNormalsOfAnEdgeParticle) {
  ParticleSet<3> set;
  set.add(Vec3(0, 0, 0), 1);  // interior: no faces
  set.add(Vec3(0, 1, 0), 1, ParticleKind::Physical, faceBit(BoxFace::MinusX) | faceBit(BoxFace::PlusY));
  EXPECT_EQ(set.facetCount(0), 0);
  EXPECT_EQ(set.outwardNormal(0), Vec3::Zero());
  EXPECT_TRUE(set.facetNormals(0).empty());

  EXPECT_EQ(set.facetCount(1), 2);
  const auto normals = set.facetNormals(1);
  ASSERT_EQ(normals.size(), 2u);
  EXPECT_EQ(normals[0], Vec3(-1, 0, 0));
  EXPECT_EQ(normals[1], Vec3(0, 1, 0));
  EXPECT_NEAR((set.outwardNormal(1) - Vec3(-1, 1, 0) / std::sqrt(2.0)).norm(), 0, 1e-15);
}

TEST(ParticleSet, FaceBitsBeyondTheDimensionAreDropped) {
  ParticleSet<1> set;
  set.add(Vec1(0), 1, ParticleKind::Physical, faceBit(BoxFace::PlusX) | faceBit(BoxFace::MinusY));
  EXPECT_EQ(set.faceMask[0], faceBit(BoxFace::PlusX));
  EXPECT_EQ(set.facetCount(0), 1);
  EXPECT_EQ(set.outwardNormal(0), Vec1(1));
}
