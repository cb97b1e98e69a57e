// lib/wiring/LambReference: a scene has the exact half-space reference exactly when it is the
// problem LambSquareLoad solves (and says why not otherwise), the reference is that solution for
// the scene's load, a probe sees it only as the normal component on the loaded face, and the
// kernel-smoothed reference tends to the exact one as the kernel shrinks.

#include "analytic/LambSquareLoad.hpp"
#include "io/scene/LoadScene.hpp"
#include "io/scene/BuildParticles.hpp"
#include "kernels/KernelFactory.hpp"
#include "wiring/LambReference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace mfwave {
namespace {

const char* const kTriangleHistory = "{ type = \"triangle\", start = 0.0, rise = 1.0, fall = 1.0 }";

// The Ding-Long-Wu problem on a small block (or, with dimension 2, its strip-load analogue on a
// rectangle); the arguments change one thing each, "" keeping the dimension's own default.
Scene lambScene(const std::string& halfWidth = "", const std::string& traction = "", const std::string& lambda = "1.0",
                const std::string& history = kTriangleHistory, int dimension = 3) {
  const bool plane = dimension == 2;
  const std::string text = R"(
[scene]
name = "lamb"
dimension = )" + std::to_string(dimension) + R"(
[geometry]
shape = )" + (plane ? "\"rectangle\"\nlower = [-2.0, -2.0]\nupper = [2.0, 0.0]"
                    : "\"block\"\nlower = [-2.0, -2.0, -2.0]\nupper = [2.0, 2.0, 0.0]") + R"(
spacing = 0.5
[material]
density = 1.0
lambda = )" + lambda + R"(
mu = 1.0
[method]
name = "finite_difference"
[[load]]
type = "surface_patch"
face = )" + (plane ? "\"+y\"\ncentre = [0.0, 0.0]" : "\"+z\"\ncentre = [0.0, 0.0, 0.0]") + R"(
half_width = )" + (!halfWidth.empty() ? halfWidth : plane ? "[0.5, 0.0]" : "[0.5, 0.5, 0.0]") + R"(
traction = )" + (!traction.empty() ? traction : plane ? "[0.0, 1.0]" : "[0.0, 0.0, 1.0]") + R"(
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

TEST(LambReference, AProbeSeesItAsTheNormalComponentOnTheLoadedFaceOrBelowTheCentre) {
  const Scene scene = lambScene();
  const ParticleSet<3> particles = buildParticles<3>(scene.geometry);
  Index surface = -1, inside = -1, axis = -1;
  for (Index a = 0; a < particles.physicalCount(); ++a) {
    const Vec3 x = particles.position(a);
    if ((x - Vec3(1.5, -0.5, 0)).norm() < 1e-12) surface = a;
    if ((x - Vec3(1.5, -0.5, -1)).norm() < 1e-12) inside = a;
    if ((x - Vec3(0, 0, -1)).norm() < 1e-12) axis = a;
  }
  ASSERT_GE(surface, 0);
  ASSERT_GE(inside, 0);
  ASSERT_GE(axis, 0);
  const auto receiver = lambReceiver(scene, particles, {"p", surface, 2, ProbeQuantity::Velocity});
  ASSERT_TRUE(receiver.has_value());
  EXPECT_DOUBLE_EQ(receiver->offset[0], 1.5);
  EXPECT_DOUBLE_EQ(receiver->offset[1], -0.5);
  EXPECT_EQ(receiver->depth, 0.0);
  EXPECT_FALSE(lambReceiver(scene, particles, {"p", surface, 0, ProbeQuantity::Velocity}).has_value());
  EXPECT_FALSE(lambReceiver(scene, particles, {"p", inside, 2, ProbeQuantity::Velocity}).has_value());  // off the axis
  const auto buried = lambReceiver(scene, particles, {"p", axis, 2, ProbeQuantity::Velocity});
  ASSERT_TRUE(buried.has_value());
  EXPECT_DOUBLE_EQ(buried->depth, 1.0);

  const std::vector<Real> times{0.5, 1.0, 2.0, 3.0};
  const LambSquareLoad exact = lambReference(scene);
  const LambExactResponse response(scene);
  const std::vector<Real> v = response.series(*receiver, times, true);
  const std::vector<Real> u = response.series(*receiver, times, false);
  for (std::size_t k = 0; k < times.size(); ++k) {
    EXPECT_EQ(v[k], exact.velocity(1.5, -0.5, times[k]));
    EXPECT_EQ(u[k], exact.displacement(1.5, -0.5, times[k]));
  }
}

// Below the centre the reference is the f-k integration of the scene's own problem: nothing before
// the P wave (depth / c_p), then the plane P wave p f(t - z / c_p) / (rho c_p) until the square's
// edges are felt (sqrt(1 + 2 l^2) / c_p from the corners, sqrt(1 + l^2) / c_p from the edges'
// midpoints), linear in the traction.
TEST(LambReference, BelowTheCentreItIsTheFrequencyWavenumberResponse) {
  const Scene scene = lambScene();
  const Real cp = std::sqrt(3.0), arrival = 1 / cp, edges = std::sqrt(1.25) / cp;
  std::vector<Real> times;
  for (Real t = 0.05; t < 0.5; t += 0.05) times.push_back(t);
  for (Real t = arrival + 0.01; t < edges; t += 0.01) times.push_back(t);
  times.push_back(6.0);
  LambReceiver buried;
  buried.depth = 1;
  const std::vector<Real> v = LambExactResponse(scene).series(buried, times, true);
  for (std::size_t k = 0; k < times.size(); ++k) {
    const Real planeWave = times[k] < arrival ? 0 : (times[k] - arrival) / cp;
    if (times[k] < edges) {
      EXPECT_NEAR(v[k], planeWave, 1e-3 * 0.3) << times[k];
    }
  }
  const std::vector<Real> doubled =
      LambExactResponse(lambScene("[0.5, 0.5, 0.0]", "[0.0, 0.0, 2.0]")).series(buried, times, true);
  for (std::size_t k = 0; k < times.size(); ++k) EXPECT_NEAR(doubled[k], 2 * v[k], 1e-12);
}

TEST(LambReference, TheKernelSmoothedResponseTendsToTheExactOneAsTheKernelShrinks) {
  const LambSquareLoad exact = lambReference(lambScene());
  const std::vector<Real> times{1.0, 1.5, 2.0, 3.0};
  const std::array<Real, 2> at{0, 0};
  const std::vector<Real> reference = LambExactResponse(lambScene()).series(LambReceiver{}, times, true);
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

// The 2-D problem: a strip on a half-plane, any Poisson ratio, the exact response at any receiver
// (LambStripLoad), the receiver's offset along the face and its depth below it.
Scene lambStripScene(const std::string& lambda = "1.0") {
  return lambScene("", "", lambda, kTriangleHistory, 2);
}

TEST(LambReference, InTwoDimensionsItIsTheStripSolutionAtEveryReceiver) {
  const Scene scene = lambStripScene();
  EXPECT_EQ(lambReferenceUnavailable(scene), "");
  EXPECT_EQ(lambReferenceUnavailable(lambStripScene("2.0")), "");  // any Poisson ratio in 2-D
  const ParticleSet<2> particles = buildParticles<2>(scene.geometry);
  Index surface = -1, inside = -1;
  for (Index a = 0; a < particles.physicalCount(); ++a) {
    const Vec2 x = particles.position(a);
    if ((x - Vec2(1.5, 0)).norm() < 1e-12) surface = a;
    if ((x - Vec2(-1.0, -1.5)).norm() < 1e-12) inside = a;
  }
  ASSERT_GE(surface, 0);
  ASSERT_GE(inside, 0);
  const auto onFace = lambReceiver<2>(scene, particles, {"p", surface, 1, ProbeQuantity::Velocity});
  const auto below = lambReceiver<2>(scene, particles, {"p", inside, 1, ProbeQuantity::Velocity});
  ASSERT_TRUE(onFace.has_value());
  ASSERT_TRUE(below.has_value());
  EXPECT_FALSE(lambReceiver<2>(scene, particles, {"p", inside, 0, ProbeQuantity::Velocity}).has_value());
  EXPECT_DOUBLE_EQ(onFace->offset[0], 1.5);
  EXPECT_EQ(onFace->depth, 0.0);
  EXPECT_DOUBLE_EQ(below->offset[0], -1.0);
  EXPECT_DOUBLE_EQ(below->depth, 1.5);
  const LambExactResponse response(scene);
  EXPECT_EQ(response.square(), nullptr);
  const LambStripLoad strip = LambStripLoad::dingLongWu();
  const std::vector<Real> times{0.5, 1.0, 2.0, 3.0};
  const std::vector<Real> v = response.series(*below, times, true), u = response.series(*onFace, times, false);
  for (std::size_t k = 0; k < times.size(); ++k) {
    EXPECT_EQ(v[k], strip.velocity(-1.0, 1.5, times[k]));
    EXPECT_EQ(u[k], strip.displacement(1.5, 0, times[k]));
  }
}

}  // namespace
}  // namespace mfwave
