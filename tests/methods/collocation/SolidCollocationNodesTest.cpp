// The nodes of RK collocation on a solid (methods/collocation/SolidCollocationNodes): surface
// points on the surface with its normal, no interior node within the gap, spacings that add up to
// the surface's length, the box's nodes fixed or free.
#include "methods/collocation/SolidCollocationNodes.hpp"

#include "core/Error.hpp"
#include "particles/BoxFace.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mfwave::solid_nodes_test {
namespace {

using Vec2 = Vec<2>;

// The half-plane below a line through the origin at 30 degrees, in the box [-4, 4] x [-4, 3].
CollocationSolid<2> inclinedHalfPlane() {
  const Vec2 n(-0.5, std::sqrt(3.0) / 2);
  CollocationSolid<2> s;
  s.distance = [n](const Vec2& x) { return x.dot(n); };
  s.normal = [n](const Vec2&) { return n; };
  s.lower = Vec2(-4, -4);
  s.upper = Vec2(4, 3);
  return s;
}

TEST(SolidCollocationNodes, SurfaceNodesLieOnTheInclinedPlaneWithItsNormalAndTheirSpacingsAddUpToItsLength) {
  const CollocationSolid<2> solid = inclinedHalfPlane();
  for (const Real dx : {0.25, 0.125}) {
    const SolidCollocationNodes<2> nodes = solidCollocationNodes<2>(solid, dx);
    ASSERT_GT(nodes.surface, 0);
    EXPECT_EQ(nodes.size(), nodes.interior + nodes.box + nodes.surface);
    Real length = 0;
    for (Index i = 0; i < nodes.size(); ++i) {
      const Vec2 x = nodes.position(i);
      const auto k = static_cast<std::size_t>(i);
      if (i < nodes.interior) {
        EXPECT_EQ(nodes.points.kind[k], CollocationRowKind::Interior);
        EXPECT_LE(solid.distance(x), -0.5 * dx + 1e-12);  // the gap
      } else if (i < nodes.interior + nodes.box) {
        EXPECT_EQ(nodes.points.kind[k], CollocationRowKind::Displacement);  // no free face: all fixed
      } else {
        EXPECT_TRUE(nodes.onSurface(i));
        EXPECT_EQ(nodes.points.kind[k], CollocationRowKind::Traction);
        EXPECT_NEAR(solid.distance(x), 0, 1e-12);
        EXPECT_NEAR((nodes.points.normal[k] - solid.normal(x)).norm(), 0, 1e-14);
        EXPECT_GE(nodes.surfaceSpacing[k], 0.6 * dx - 1e-12);
        EXPECT_LE(nodes.surfaceSpacing[k], 1.6 * dx);  // the ends: both neighbours on one side
        length += nodes.surfaceSpacing[k];
      }
    }
    // the line within the box less the gap at each end: from x = -4 + dx/2 to x = 4 - dx/2, over cos 30
    const Real expected = (8 - dx) / std::cos(M_PI / 6);
    EXPECT_NEAR(length, expected, 2 * dx) << "dx = " << dx;  // each end counts a neighbour twice
  }
}

TEST(SolidCollocationNodes, ADiscInTheBoxHasItsPerimeterInSurfaceSpacingsAndFreeBoxFacesHaveTractionRows) {
  CollocationSolid<2> solid;
  const Real radius = 1.3;
  // the box with a hole: distance to the solid's own surface, the circle, negative in the material
  solid.distance = [radius](const Vec2& x) { return radius - x.norm(); };
  solid.normal = [](const Vec2& x) { return Vec2(-x / x.norm()); };
  solid.lower = Vec2(-3, -3);
  solid.upper = Vec2(3, 3);
  solid.freeFaces = faceBit(BoxFace::PlusY);
  const Real dx = 0.125;
  const SolidCollocationNodes<2> nodes = solidCollocationNodes<2>(solid, dx);
  Real perimeter = 0;
  Index freeRows = 0, fixedRows = 0;
  for (Index i = nodes.interior; i < nodes.size(); ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (nodes.onSurface(i)) {
      EXPECT_NEAR(nodes.position(i).norm(), radius, 1e-12);
      perimeter += nodes.surfaceSpacing[k];
    } else if (nodes.points.kind[k] == CollocationRowKind::Traction) {
      EXPECT_EQ(nodes.points.normal[k], Vec2(0, 1));
      EXPECT_NEAR(nodes.position(i)[1], 3, 1e-12);
      ++freeRows;
    } else {
      ++fixedRows;
    }
  }
  EXPECT_NEAR(perimeter / (2 * M_PI * radius), 1, 0.03);
  EXPECT_EQ(freeRows, 47);             // the +y face less its two corners
  EXPECT_EQ(fixedRows, 4 * 48 - 47);   // the rest of the box's perimeter
}

TEST(SolidCollocationNodes, RefusesASpacingThatDoesNotDivideTheBoxAndASolidWithNoInteriorNode) {
  const CollocationSolid<2> solid = inclinedHalfPlane();
  EXPECT_THROW(solidCollocationNodes<2>(solid, 0.3), InputError);
  CollocationSolid<2> thin = solid;
  thin.distance = [](const Vec2& x) { return std::abs(x[1]) - 0.01; };
  thin.normal = [](const Vec2& x) { return Vec2(0, x[1] >= 0 ? 1 : -1); };
  try {
    solidCollocationNodes<2>(thin, 0.25);
    FAIL() << "a solid thinner than the gap has no interior node";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "geometry.solid");
  }
}

}  // namespace
}  // namespace mfwave::solid_nodes_test
