#include "spectra/LatticeMethods.hpp"

#include "spectra/VeryWeakSphDispersion.hpp"
#include "core/Error.hpp"

#include <algorithm>

namespace mfwave {

const std::vector<std::string>& latticeMethodNames() {
  static const std::vector<std::string> names = {"finite_difference", "vwsph_published", "vwsph_consistent",
                                                 "vwsph_galerkin", "rkcm", "rbcm", "ulsph", "ulsph_corrected"};
  return names;
}

bool latticeMethodAvailable(const std::string& method, int dimension) {
  const auto& names = latticeMethodNames();
  if (std::find(names.begin(), names.end(), method) == names.end()) return false;
  return method != "rbcm" || dimension == 1;
}

template <int D>
MethodLatticeStencil<D> latticeMethodStencil(const std::string& method, const LatticeMethodSettings& s, Real spacing,
                                             const std::string& key) {
  if (!latticeMethodAvailable(method, D))
    throw InputError(key, "'" + method + "' is not a lattice method in " + std::to_string(D) +
                              "-D (finite_difference, vwsph_published, vwsph_consistent, vwsph_galerkin, rkcm, rbcm (1-D), "
                              "ulsph, ulsph_corrected)");
  if (method == "finite_difference") return finiteDifferenceInteriorStencil<D>(spacing, s.material.pWaveSpeed());
  if (method == "rkcm")
    return collocationInteriorStencil<D>(CollocationBasis::ReproducingKernel, s.rkOrder, s.rkSupportRatio, s.material,
                                         spacing);
  if (method == "rbcm")
    return collocationInteriorStencil<D>(CollocationBasis::RadialBasis, 0, s.rbShapeRatio, s.material, spacing);
  if (method.rfind("vwsph_", 0) == 0) {
    const auto variant = parseVeryWeakSphDispersionVariant(method.substr(6), key);
    const auto lattice =
        veryWeakSphInteriorStencil<D>(variant, s.kernel, s.smoothingLengthRatio, s.material, spacing);
    MethodLatticeStencil<D> result;
    result.acceleration = lattice.stencil;
    result.translationDifference = lattice.translationDifference;
    result.halfWidth = lattice.halfWidth;
    return result;
  }
  return updatedLagrangianSphInteriorStencil<D>(updatedLagrangianSphSettings(method, s), spacing);
}

UpdatedLagrangianSphOptions updatedLagrangianSphSettings(const std::string& method, const LatticeMethodSettings& s) {
  UpdatedLagrangianSphOptions options;
  options.material = s.material;
  options.kernel = s.kernel;
  options.smoothingLengthRatio = s.smoothingLengthRatio;
  options.kernelGradientCorrection = method == "ulsph_corrected";
  return options;
}

template MethodLatticeStencil<1> latticeMethodStencil<1>(const std::string&, const LatticeMethodSettings&, Real,
                                                         const std::string&);
template MethodLatticeStencil<2> latticeMethodStencil<2>(const std::string&, const LatticeMethodSettings&, Real,
                                                         const std::string&);
template MethodLatticeStencil<3> latticeMethodStencil<3>(const std::string&, const LatticeMethodSettings&, Real,
                                                         const std::string&);

}  // namespace mfwave
