#include "study/CollocationSpec.hpp"

#include <string>

#include "analysis/InteriorStability.hpp"
#include "analysis/MethodLatticeStencils.hpp"
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

CollocationGrowingModes rkPlaneStrainGrowingModes(int order, Real ratio, const Material& material) {
  const MethodLatticeStencil<2> rows =
      collocationInteriorStencil<2>(CollocationBasis::ReproducingKernel, order, ratio, material, 1.0);
  const InteriorStability<2> verdict = interiorStability<2>(rows.acceleration, rows.mass, 1.0, 32);
  CollocationGrowingModes out;
  if (!verdict.growing()) return out;
  std::ostringstream what;
  what << "the RK collocation operator (method.order = " << order << ", method.support_ratio = " << ratio
       << ") has growing modes: its interior " << verdict.describe() << "; such a mode grows at every time step";
  out.what = what.str();
  out.advice = "a smaller method.support_ratio, e.g. 2.5, is stable in 2-D";
  return out;
}

}  // namespace mfwave
