// lib/wiring/CollocationSpec: the collocation [method] keys are read by method name into typed
// options, another method is refused at method.name, and the shape functions made from them are
// the asked kind with the asked parameters: a reproducing kernel of order m reproduces degree-m
// polynomials with support a = ratio h, a radial basis interpolates its nodes; plane-strain RK rows
// grow from a support of about 2.77 h on, 3-D rows from 2.5 h on.

#include "core/Error.hpp"
#include "io/scene/LoadScene.hpp"
#include "io/scene/SceneError.hpp"
#include "methods/collocation/RadialBasisShapeFunctions.hpp"
#include "methods/collocation/ReproducingKernelShapeFunctions.hpp"
#include "wiring/CollocationSpec.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace mfwave {
namespace {

SceneReader readerFor(const std::string& method) {
  SceneSchema schema = SceneSchema::common();
  schema.addChoice("method.name", "reproducing_kernel");
  schema.addChoice("method.name", "radial_basis");
  schema.add("method.order", ValueType::Integer).defaultsTo("2").when("name = reproducing_kernel");
  schema.add("method.support_ratio", ValueType::Number).defaultsTo("3.3").when("name = reproducing_kernel");
  schema.add("method.basis", ValueType::String).defaultsTo("\"inverse_multiquadric\"").when("name = radial_basis");
  schema.add("method.shape_ratio", ValueType::Number).defaultsTo("1.0").when("name = radial_basis");
  const std::string text = "[scene]\nname = \"bar\"\ndimension = 1\n[geometry]\nshape = \"line\"\nlower = [0.0]\n"
                           "upper = [1.0]\nspacing = 0.1\n[material]\ndensity = 1.0\nlambda = 1.0\nmu = 1.0\n"
                           "[method]\n" + method + "[integrator]\nend_time = 1.0\n";
  return parseScene(text, "bar.toml", {}, schema);
}

TEST(CollocationSpec, ReadsTheKeysOfItsMethodTyped) {
  SceneReader rk = readerFor("name = \"reproducing_kernel\"\norder = 3\nsupport_ratio = 2.5\n");
  const CollocationSpec a = readCollocationSpec(rk, "reproducing_kernel", "bar1d");
  EXPECT_EQ(a.kind, CollocationShapeKind::ReproducingKernel);
  EXPECT_EQ(a.order, 3);
  EXPECT_EQ(a.supportRatio, 2.5);
  EXPECT_EQ(a.describe(), "reproducing kernel order 3, method.support_ratio = 2.5");

  SceneReader rb = readerFor("name = \"radial_basis\"\nbasis = \"multiquadric\"\nshape_ratio = 2.0\n");
  const CollocationSpec b = readCollocationSpec(rb, "radial_basis", "bar1d");
  EXPECT_EQ(b.kind, CollocationShapeKind::RadialBasis);
  EXPECT_EQ(b.radialBasis, "multiquadric");
  EXPECT_EQ(b.shapeRatio, 2.0);
  EXPECT_EQ(b.describe(), "radial basis multiquadric, method.shape_ratio = 2");

  SceneReader other = readerFor("name = \"reproducing_kernel\"\n");
  try {
    readCollocationSpec(other, "finite_difference", "bar1d");
    FAIL() << "another method is refused";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "method.name");
    EXPECT_NE(std::string(e.what()).find("bar1d uses reproducing_kernel or radial_basis"), std::string::npos);
  }
}

TEST(CollocationSpec, MakesTheShapeFunctionsItDescribes) {
  const Real h = 0.1;
  Coordinates<1> nodes;
  for (int i = 0; i <= 10; ++i) nodes[0].push_back(h * i);

  CollocationSpec rk;
  rk.order = 2;
  rk.supportRatio = 2.5;
  const auto kernel = makeCollocationShapes<1>(rk, nodes, h);
  ASSERT_NE(dynamic_cast<const ReproducingKernelShapeFunctions<1>*>(kernel.get()), nullptr);
  ShapeFunctionValues<1> values;
  const Real x = 0.437;
  kernel->evaluate(Vec1(x), 0, values);
  Real quadratic = 0;
  for (Index k = 0; k < values.size(); ++k) {
    const Real xk = nodes[0][static_cast<std::size_t>(values.nodes[static_cast<std::size_t>(k)])];
    quadratic += values.value[static_cast<std::size_t>(k)] * xk * xk;
    EXPECT_LT(std::abs(xk - x), 2.5 * h + 1e-12);  // the support is ratio h
  }
  EXPECT_NEAR(quadratic, x * x, 1e-12);  // order 2 reproduces x^2

  CollocationSpec rb;
  rb.kind = CollocationShapeKind::RadialBasis;
  rb.radialBasis = "inverse_multiquadric";
  rb.shapeRatio = 1;
  const auto basis = makeCollocationShapes<1>(rb, nodes, h);
  ASSERT_NE(dynamic_cast<const RadialBasisShapeFunctions<1>*>(basis.get()), nullptr);
  basis->evaluate(Vec1(nodes[0][4]), 0, values);
  for (Index k = 0; k < values.size(); ++k)
    EXPECT_NEAR(values.value[static_cast<std::size_t>(k)], values.nodes[static_cast<std::size_t>(k)] == 4 ? 1.0 : 0.0,
                1e-8);  // interpolates its nodes
}

TEST(CollocationSpec, PlaneStrainRkSupportsFromAboutTwoPointEightOnHaveGrowingInteriorModes) {
  const Material material = Material::fromLame(1, 1, 1);
  for (const Real stable : {2.2, 2.5, 2.7})
    EXPECT_FALSE(rkPlaneStrainGrowingModes(2, stable, material).growing()) << stable;
  const CollocationGrowingModes grows = rkPlaneStrainGrowingModes(2, 3.0, material);
  ASSERT_TRUE(grows.growing());
  EXPECT_NE(grows.what.find("method.order = 2, method.support_ratio = 3)"), std::string::npos) << grows.what;
  EXPECT_NE(grows.advice.find("method.support_ratio"), std::string::npos);
}

// docs/studies/stability-atlas.md: in 3-D m = 2 grows from a / h = 2.5 (lamb2d's default) and 2.2 is
// the widest stable support, which the advice names (lamb3d's default).
TEST(CollocationSpec, ThreeDimensionalRkSupportsFromTwoPointFiveOnHaveGrowingInteriorModes) {
  const Material material = Material::fromLame(1, 1, 1);
  EXPECT_FALSE(rkGrowingModes(3, 2, 2.2, material).growing());
  const CollocationGrowingModes grows = rkGrowingModes(3, 2, 2.5, material);
  ASSERT_TRUE(grows.growing());
  EXPECT_NE(grows.what.find("method.support_ratio = 2.5)"), std::string::npos) << grows.what;
  EXPECT_NE(grows.advice.find("2.2"), std::string::npos) << grows.advice;
  EXPECT_THROW(rkGrowingModes(1, 2, 2.2, material), InputError);
}

}  // namespace
}  // namespace mfwave
