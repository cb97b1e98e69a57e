#include "methods/very_weak_sph/Deconvolution.hpp"

#include "core/Error.hpp"
#include "methods/very_weak_sph/KernelCorrection.hpp"

#include <string>

namespace mfwave {

template <int D>
ParticleMatrix deconvolutionMatrix(const ParticleSet<D>& particles, const NeighbourList& neighbours,
                                   const Kernel& kernel, const std::vector<Real>& volumes, DeconvolutionForm form) {
  // Start from the kernel estimate S (same pattern, self included) and rewrite each row.
  ParticleMatrix matrix = smoothingMatrix(particles, neighbours, kernel, volumes);
  // alpha_a = 1 / s_a (eq. (29)); only the plain form needs it.
  const std::vector<Real> alpha = kernelCorrectionFactors(particles, neighbours, kernel, volumes, true);
  const Index n = matrix.rows();
  const int* outer = matrix.outerIndexPtr();
  const int* inner = matrix.innerIndexPtr();
  Real* values = matrix.valuePtr();
#pragma omp parallel for schedule(static)
  for (Index a = 0; a < n; ++a) {
    Real self = 0;
    for (int k = outer[a]; k < outer[a + 1]; ++k)
      if (inner[k] == a) self = values[k];
    // Ding-Long-Wu eq. (35): u_a = (u^h_a - sum_{b != a} S_ab u^h_b) / S_aa in normalised form,
    // where S_aa = W(0) V_a / s_a; the plain form divides u^h_a by W(0) V_a = s_a S_aa instead.
    const Real diagonal = form == DeconvolutionForm::Normalised ? 1 / self : alpha[static_cast<std::size_t>(a)] / self;
    for (int k = outer[a]; k < outer[a + 1]; ++k) values[k] = inner[k] == a ? diagonal : -values[k] / self;
  }
  return matrix;
}

Vector deconvolve(const ParticleMatrix& matrix, const Vector& field, int dimension) {
  Vector out;
  multiplyComponents(matrix, field, dimension, out);
  return out;
}

Real deconvolveAt(const ParticleMatrix& matrix, Index particle, const Vector& field, int dimension, int component) {
  if (particle < 0 || particle >= matrix.rows())
    throw InputError("particle", "index " + std::to_string(particle) + " is not a physical particle");
  if (component < 0 || component >= dimension)
    throw InputError("component", "must be in [0, " + std::to_string(dimension) + ")");
  if (field.size() != dimension * static_cast<Index>(matrix.cols()))
    throw InputError("field", "need " + std::to_string(dimension) + " components per particle");
  Real sum = 0;
  for (ParticleMatrix::InnerIterator it(matrix, static_cast<int>(particle)); it; ++it)
    sum += it.value() * field[dimension * static_cast<Index>(it.col()) + component];
  return sum;
}

template ParticleMatrix deconvolutionMatrix<1>(const ParticleSet<1>&, const NeighbourList&, const Kernel&,
                                               const std::vector<Real>&, DeconvolutionForm);
template ParticleMatrix deconvolutionMatrix<2>(const ParticleSet<2>&, const NeighbourList&, const Kernel&,
                                               const std::vector<Real>&, DeconvolutionForm);
template ParticleMatrix deconvolutionMatrix<3>(const ParticleSet<3>&, const NeighbourList&, const Kernel&,
                                               const std::vector<Real>&, DeconvolutionForm);

}  // namespace mfwave
