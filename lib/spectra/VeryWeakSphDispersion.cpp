#include "spectra/VeryWeakSphDispersion.hpp"

#include "core/Error.hpp"
#include "kernels/KernelFactory.hpp"
#include "methods/very_weak_sph/VeryWeakSph.hpp"
#include "neighbours/CellList.hpp"
#include "neighbours/NeighbourList.hpp"
#include "particles/BoxFace.hpp"
#include "particles/GhostLayers.hpp"
#include "particles/Lattice.hpp"

#include <cmath>

namespace mfwave {

namespace {

template <int D>
Index findParticle(const ParticleSet<D>& particles, const Vec<D>& x, Real tolerance) {
  for (Index i = 0; i < particles.physicalCount(); ++i)
    if ((particles.position(i) - x).norm() < tolerance) return i;
  throw Error("veryWeakSphInteriorStencil: no lattice particle at the expected position");
}

}  // namespace

const std::vector<std::string>& veryWeakSphDispersionVariantNames() {
  static const std::vector<std::string> names = {"published", "published_row_sum", "consistent", "galerkin"};
  return names;
}

const char* veryWeakSphDispersionVariantName(VeryWeakSphDispersionVariant variant) {
  switch (variant) {
    case VeryWeakSphDispersionVariant::Published: return "published";
    case VeryWeakSphDispersionVariant::PublishedRowSumCorrected: return "published_row_sum";
    case VeryWeakSphDispersionVariant::Consistent: return "consistent";
    case VeryWeakSphDispersionVariant::Galerkin: return "galerkin";
  }
  return "?";
}

VeryWeakSphDispersionVariant parseVeryWeakSphDispersionVariant(const std::string& name, const std::string& key) {
  if (name == "published") return VeryWeakSphDispersionVariant::Published;
  if (name == "published_row_sum") return VeryWeakSphDispersionVariant::PublishedRowSumCorrected;
  if (name == "consistent") return VeryWeakSphDispersionVariant::Consistent;
  if (name == "galerkin") return VeryWeakSphDispersionVariant::Galerkin;
  throw InputError(key, "unknown variant '" + name + "' (published, published_row_sum, consistent, galerkin)");
}

template <int D>
VeryWeakSphLatticeStencil<D> veryWeakSphInteriorStencil(VeryWeakSphDispersionVariant variant,
                                                        const std::string& kernelName, Real smoothingLengthRatio,
                                                        const Material& material, Real spacing) {
  if (!(smoothingLengthRatio > 0) || !std::isfinite(smoothingLengthRatio))
    throw InputError("smoothing_length_ratio", "must be positive and finite");
  if (!(spacing > 0) || !std::isfinite(spacing)) throw InputError("spacing", "must be positive and finite");
  VeryWeakSphOptions options;
  options.material = material;
  if (variant == VeryWeakSphDispersionVariant::Consistent) options.variant = VeryWeakSphVariant::Consistent;
  if (variant == VeryWeakSphDispersionVariant::Galerkin) options.variant = VeryWeakSphVariant::Galerkin;

  const auto kernel = makeKernel(kernelName, D, smoothingLengthRatio * spacing);
  // Support in lattice spacings (the support is open: W = 0 at its radius).
  const int reach = static_cast<int>(std::ceil(kernel->supportRadius() / spacing - 1e-9));
  VeryWeakSphLatticeStencil<D> result;
  // The centre's neighbours and their neighbours are interior (a corrected method may reach two
  // supports), plus one spacing for the shifted row of the translation check.
  result.halfWidth = 2 * reach + 2;
  result.ghostLayers = reach + 1;
  result.spacing = spacing;
  result.smoothingLength = smoothingLengthRatio * spacing;
  const Vec<D> upper = Vec<D>::Constant(result.halfWidth * spacing);
  const Vec<D> lower = -upper;
  ParticleSet<D> particles = makeLattice<D>(lower, upper, spacing);
  result.ghostParticles = addGhostLayers<D>(particles, lower, upper, spacing, result.ghostLayers, allFaces(D));
  result.physicalParticles = particles.physicalCount();
  const NeighbourList neighbours =
      buildNeighbourList(CellList<D>(particles, kernel->supportRadius()), particles.physicalCount());
  const VeryWeakSph<D> method = assembleVeryWeakSph(particles, neighbours, *kernel, options);

  const Index centre = findParticle<D>(particles, Vec<D>::Zero(), 1e-9 * spacing);
  Vec<D> shift = Vec<D>::Zero();
  shift(0) = spacing;
  const Index next = findParticle<D>(particles, shift, 1e-9 * spacing);
  result.stencil = extractLatticeStencil(method.system, particles, centre);
  result.translationDifference =
      stencilDifference(result.stencil, extractLatticeStencil(method.system, particles, next), 1e-9 * spacing);
  if (variant == VeryWeakSphDispersionVariant::PublishedRowSumCorrected)
    result.stencil = result.stencil.withRowSumCorrection();
  return result;
}

template VeryWeakSphLatticeStencil<1> veryWeakSphInteriorStencil<1>(VeryWeakSphDispersionVariant, const std::string&,
                                                                    Real, const Material&, Real);
template VeryWeakSphLatticeStencil<2> veryWeakSphInteriorStencil<2>(VeryWeakSphDispersionVariant, const std::string&,
                                                                    Real, const Material&, Real);
template VeryWeakSphLatticeStencil<3> veryWeakSphInteriorStencil<3>(VeryWeakSphDispersionVariant, const std::string&,
                                                                    Real, const Material&, Real);

}  // namespace mfwave
