// lib/study/LambReference: a scene has the exact half-space reference exactly when it is the
// problem LambSquareLoad solves (and says why not otherwise), the reference is that solution for
// the scene's load, a probe sees it only as the normal component on the loaded face, and the
// kernel-smoothed reference tends to the exact one as the kernel shrinks.

#include "analytic/LambSquareLoad.hpp"
#include "io/scene/LoadScene.hpp"
#include "io/scene/BuildParticles.hpp"
#include "kernels/KernelFactory.hpp"
#include "study/LambReference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace mfwave {
namespace {

// The Ding-Long-Wu problem on a small block; the arguments change one thing each.
Scene lambScene(const std::string& halfWidth = "[0.5, 0.5, 0.0]", const std::string& traction = "[0.0, 0.0, 1.0]",
                const std::string& lambda = "1.0",
                const std::string& history = "{ type = \"triangle\", start = 0.0, rise = 1.0, fall = 1.0 }") {
  const std::string text = R"(
[scene]
name = "lamb"
dimension = 3
[geometry]
shape = "block"
lower = [-2.0, -2.0, -2.0]
upper = [2.0, 2.0, 0.0]
spacing = 0.5
[material]
density = 1.0
lambda = )" + lambda + R"(
mu = 1.0
[method]
name = "finite_difference"
[[load]]
type = "surface_patch"
face = "+z"
centre = [0.0, 0.0, 0.0]
half_width = )" + halfWidth + R"(
traction = )" + traction + R"(
time_function = )" + history + R"(
[integrator]
end_time = 1.0
)";
  SceneReader reader = parseScene(text, "lamb.toml", {}, SceneSchema::common());
  return readScene(reader);
}

TEST(LambReference, ExistsExactlyForTheSquareNormalPatchOnAPoissonSolid) {
  EXPECT_EQ(lambReferenceUnavailable(lambScene()), "");
  EXPECT_NE(lambReferenceUnavailable(lambScene("[0.5, 0.25, 0.0]")).find("square"), std::string::npos);
  EXPECT_NE(lambReferenceUnavailable(lambScene("[0.5, 0.5, 0.0]", "[0.2, 0.0, 1.0]")).find("normal traction"),
            std::string::npos);
  EXPECT_NE(lambReferenceUnavailable(lambScene("[0.5, 0.5, 0.0]", "[0.0, 0.0, 1.0]", "2.0")).find("lambda = mu"),
            std::string::npos);
  EXPECT_NE(lambReferenceUnavailable(
                lambScene("[0.5, 0.5, 0.0]", "[0.0, 0.0, 1.0]", "1.0", "{ type = \"ricker\", peak_frequency = 1.0 }"))
                .find("piecewise-linear"),
            std::string::npos);
}

TEST(LambReference, IsThePublishedProblemsSolutionForItsScene) {
  const LambSquareLoad fromScene = lambReference(lambScene());
  const LambSquareLoad published = LambSquareLoad::dingLongWu();
  for (const Real t : {0.5, 1.3, 2.7, 4.0})
    for (const Real x : {0.0, 0.25, 2.0}) {
      EXPECT_NEAR(fromScene.velocity(x, 0, t), published.velocity(x, 0, t), 1e-12);
      EXPECT_NEAR(fromScene.displacement(x, 0.1, t), published.displacement(x, 0.1, t), 1e-12);
    }
  // Linear in the traction: twice the load, twice the response.
  const LambSquareLoad doubled = lambReference(lambScene("[0.5, 0.5, 0.0]", "[0.0, 0.0, 2.0]"));
  EXPECT_NEAR(doubled.velocity(0.25, 0, 1.3), 2 * published.velocity(0.25, 0, 1.3), 1e-12);
}

TEST(LambReference, AProbeSeesItAsTheNormalComponentOnTheLoadedFace) {
  const Scene scene = lambScene();
  const ParticleSet<3> particles = buildParticles<3>(scene.geometry);
  Index surface = -1, inside = -1;
  for (Index a = 0; a < particles.physicalCount(); ++a) {
    const Vec3 x = particles.position(a);
    if ((x - Vec3(1.5, -0.5, 0)).norm() < 1e-12) surface = a;
    if ((x - Vec3(1.5, -0.5, -1)).norm() < 1e-12) inside = a;
  }
  ASSERT_GE(surface, 0);
  ASSERT_GE(inside, 0);
  const auto offset = lambSurfaceOffset(scene, particles, {"p", surface, 2, ProbeQuantity::Velocity});
  ASSERT_TRUE(offset.has_value());
  EXPECT_DOUBLE_EQ((*offset)[0], 1.5);
  EXPECT_DOUBLE_EQ((*offset)[1], -0.5);
  EXPECT_FALSE(lambSurfaceOffset(scene, particles, {"p", surface, 0, ProbeQuantity::Velocity}).has_value());
  EXPECT_FALSE(lambSurfaceOffset(scene, particles, {"p", inside, 2, ProbeQuantity::Velocity}).has_value());

  const std::vector<Real> times{0.5, 1.0, 2.0, 3.0};
  const LambSquareLoad exact = lambReference(scene);
  const std::vector<Real> v = lambExactSeries(exact, *offset, times, true);
  const std::vector<Real> u = lambExactSeries(exact, *offset, times, false);
  for (std::size_t k = 0; k < times.size(); ++k) {
    EXPECT_EQ(v[k], exact.velocity(1.5, -0.5, times[k]));
    EXPECT_EQ(u[k], exact.displacement(1.5, -0.5, times[k]));
  }
}

TEST(LambReference, TheKernelSmoothedResponseTendsToTheExactOneAsTheKernelShrinks) {
  const LambSquareLoad exact = lambReference(lambScene());
  const std::vector<Real> times{1.0, 1.5, 2.0, 3.0};
  const std::array<Real, 2> at{0, 0};
  const std::vector<Real> reference = lambExactSeries(exact, at, times, true);
  const auto distance = [&](Real h) {
    const auto kernel = makeKernel("cubic_spline", 3, h);
    const std::vector<Real> smoothed = kernelSmoothedLambSeries(exact, *kernel, at, times, true);
    Real d = 0, n = 0;
    for (std::size_t k = 0; k < times.size(); ++k) {
      d += std::pow(smoothed[k] - reference[k], 2);
      n += reference[k] * reference[k];
    }
    return std::sqrt(d / n);
  };
  const Real wide = distance(0.4), narrow = distance(0.01);
  EXPECT_GT(wide, 1e-2);   // a kernel as wide as the patch blurs the load
  EXPECT_LT(narrow, 1e-3);
}

}  // namespace
}  // namespace mfwave
