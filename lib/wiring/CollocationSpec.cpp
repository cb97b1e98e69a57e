#include "wiring/CollocationSpec.hpp"

#include "io/scene/Format.hpp"

#include <string>

#include "numerics/InteriorStability.hpp"
#include "spectra/MethodLatticeStencils.hpp"
#include "core/Error.hpp"
#include "methods/collocation/RadialBasisFunction.hpp"
#include "methods/collocation/RadialBasisShapeFunctions.hpp"
#include "methods/collocation/ReproducingKernelShapeFunctions.hpp"

#include <sstream>

namespace mfwave {

std::string CollocationSpec::describe() const {
  std::ostringstream s;
  if (kind == CollocationShapeKind::RadialBasis)
    s << "radial basis " << radialBasis << ", method.shape_ratio = " << shapeRatio;
  else
    s << "reproducing kernel order " << order << ", method.support_ratio = " << supportRatio;
  return s.str();
}

void addCollocationKeys(SceneSchema& schema, const CollocationKeyDefaults& defaults) {
  using T = ValueType;
  if (defaults.reproducingKernel) {
    const std::string rk = "name = reproducing_kernel";
    schema.addChoice("method.name", "reproducing_kernel");
    // 1 .. 3 here; readCollocationSpec refuses m = 1 with the reason (collocation needs second derivatives).
    schema.add("method.order", T::Integer).withUnit("-").defaultsTo("2").between(1, 3).when(rk)
        .describedAs("RK basis order m (2 or 3: collocation needs second derivatives)");
    KeySpec& support = schema.add("method.support_ratio", T::Number).withUnit("-").positive().when(rk);
    if (defaults.supportRatio > 0) support.defaultsTo(scene::tomlNumber(defaults.supportRatio));
    else support.defaultsToNote(defaults.supportNote);
    support.describedAs("cubic B-spline support radius a / h" +
                        (defaults.supportAdvice.empty() ? std::string() : " (" + defaults.supportAdvice + ")"));
  }
  if (!defaults.radialBasis) return;
  const std::string rb = "name = radial_basis";
  schema.addChoice("method.name", "radial_basis");
  schema.add("method.basis", T::String).defaultsTo("\"inverse_multiquadric\"").oneOf(radialBasisNames()).when(rb)
      .describedAs("radial basis function");
  schema.add("method.shape_ratio", T::Number).withUnit("-").defaultsTo(scene::tomlNumber(defaults.shapeRatio)).positive()
      .when(rb).describedAs("RBF shape parameter a_r / h");
}

CollocationSpec readCollocationSpec(SceneReader& reader, const std::string& methodName, const std::string& program) {
  CollocationSpec spec;
  if (methodName == "reproducing_kernel") {
    // The fallback 2 is every schema's default; a schema that shares method.order with another
    // method (lamb2d: the spectral elements' N) registers a wider range, so the RK range is checked here.
    spec.order = static_cast<int>(reader.integer("method.order", 2));
    if (spec.order < 2 || spec.order > 3)
      reader.fail("method.order", "RK collocation needs basis order m = 2 or 3 (second derivatives), got " +
                                      std::to_string(spec.order));
    spec.supportRatio = reader.number("method.support_ratio");
  } else if (methodName == "radial_basis") {
    spec.kind = CollocationShapeKind::RadialBasis;
    spec.radialBasis = reader.string("method.basis");
    spec.shapeRatio = reader.number("method.shape_ratio");
  } else {
    reader.fail("method.name", program + " uses reproducing_kernel or radial_basis");
  }
  return spec;
}

template <int D>
std::unique_ptr<ShapeFunctions<D>> makeCollocationShapes(const CollocationSpec& spec, const Coordinates<D>& nodes,
                                                         Real h) {
  if (spec.kind == CollocationShapeKind::RadialBasis)
    return std::make_unique<RadialBasisShapeFunctions<D>>(nodes,
                                                          makeRadialBasisFunction(spec.radialBasis, spec.shapeRatio * h));
  return std::make_unique<ReproducingKernelShapeFunctions<D>>(nodes, spec.order, spec.supportRatio * h);
}

template std::unique_ptr<ShapeFunctions<1>> makeCollocationShapes<1>(const CollocationSpec&, const Coordinates<1>&, Real);
template std::unique_ptr<ShapeFunctions<2>> makeCollocationShapes<2>(const CollocationSpec&, const Coordinates<2>&, Real);
template std::unique_ptr<ShapeFunctions<3>> makeCollocationShapes<3>(const CollocationSpec&, const Coordinates<3>&, Real);

namespace {

// Where the interior rows' spectrum on a periodic lattice of `cells` per axis grows ("" when it
// does not).
template <int D>
std::string rkInteriorGrowth(int order, Real ratio, const Material& material, int cells) {
  const MethodLatticeStencil<D> rows =
      collocationInteriorStencil<D>(CollocationBasis::ReproducingKernel, order, ratio, material, 1.0);
  const InteriorStability<D> verdict = interiorStability<D>(rows.acceleration, rows.mass, 1.0, cells);
  return verdict.growing() ? verdict.describe() : std::string();
}

}  // namespace

CollocationGrowingModes rkGrowingModes(int dimension, int order, Real ratio, const Material& material) {
  if (dimension != 2 && dimension != 3)
    throw InputError("scene.dimension", "the RK growing-mode check is for 2-D and 3-D operators");
  // 3-D: 24 cells per axis, the stability atlas's 3-D lattice (docs/studies/stability-atlas.md),
  // on which m = 2 grows from a / h = 2.5 and 2.2 is stable; 2-D keeps its 32.
  const std::string where = dimension == 2 ? rkInteriorGrowth<2>(order, ratio, material, 32)
                                           : rkInteriorGrowth<3>(order, ratio, material, 24);
  const bool growing = !where.empty();
  CollocationGrowingModes out;
  if (!growing) return out;
  std::ostringstream what;
  what << "the RK collocation operator (method.order = " << order << ", method.support_ratio = " << ratio
       << ") has growing modes: its interior " << where << "; such a mode grows at every time step";
  out.what = what.str();
  out.advice = dimension == 2 ? "a smaller method.support_ratio, e.g. 2.5, is stable in 2-D"
                              : "a smaller method.support_ratio, e.g. 2.2 (the widest stable 3-D support in "
                                "docs/studies/stability-atlas.md), is stable in 3-D";
  return out;
}

}  // namespace mfwave
