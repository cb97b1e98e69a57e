#include "methods/total_lagrangian_sph/TotalLagrangianSph.hpp"

#include "numerics/StableTimeStep.hpp"
#include "core/Error.hpp"
#include "kernels/KernelFactory.hpp"

#include <cmath>
#include <string>

namespace mfwave {
namespace {

// Below this many particles a pass runs on one thread (thread start-up would cost more).
constexpr Index kParallelParticles = 2000;

// The system linearised about rest: a(eps u) / eps (no loads: a(0) = 0).
template <int D>
class LinearisedAtRest : public SecondOrderSystem {
 public:
  LinearisedAtRest(TotalLagrangianSph<D>& system, Real scale) : system_(system), scale_(scale), scaled_(system.size()) {}
  Index size() const override { return system_.size(); }
  void acceleration(Real t, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector> v, Eigen::Ref<Vector> a) override {
    scaled_ = scale_ * u;
    system_.acceleration(t, scaled_, v, a);
    a /= scale_;
  }
  bool dependsOnVelocity() const override { return false; }

 private:
  TotalLagrangianSph<D>& system_;
  Real scale_;
  Vector scaled_;
};

}  // namespace

template <int D>
TotalLagrangianSph<D>::TotalLagrangianSph(const ParticleSet<D>& particles, TotalLagrangianSphOptions options)
    : options_(std::move(options)) {
  if (!(options_.smoothingLengthRatio > 0) || !std::isfinite(options_.smoothingLengthRatio))
    throw InputError("smoothing_length_ratio", "must be positive and finite");
  if (!(options_.hourglassFactor >= 0) || !std::isfinite(options_.hourglassFactor))
    throw InputError("hourglass_factor", "must be non-negative and finite");
  if (particles.physicalCount() == 0) throw InputError("particles", "no physical particles");
  Real totalVolume = 0;
  for (Index i = 0; i < particles.physicalCount(); ++i) totalVolume += particles.volume[static_cast<std::size_t>(i)];
  // The initial spacing: the D-th root of the mean volume (exact for a lattice).
  const Real spacing = std::pow(totalVolume / static_cast<Real>(particles.physicalCount()), 1.0 / D);
  smoothingLength_ = options_.smoothingLengthRatio * spacing;
  const std::unique_ptr<Kernel> kernel = makeKernel(options_.kernel, D, smoothingLength_);
  pairs_ = makeReferencePairs<D>(particles, *kernel, options_.interacts);
  const auto n = static_cast<std::size_t>(pairs_.count());
  fixed_.assign(n, 0);
  displacementGradient_.resize(n);
  stressTimesCorrection_.resize(n);
}

template <int D>
Real TotalLagrangianSph<D>::meanNeighbourCount() const {
  return static_cast<Real>(pairs_.pairCount()) / static_cast<Real>(pairs_.count());
}

template <int D>
void TotalLagrangianSph<D>::fixParticles(const std::vector<Index>& particles) {
  for (Index i : particles) {
    if (i < 0 || i >= pairs_.count())
      throw InputError("particles", "index " + std::to_string(i) + " is not a particle (there are " +
                                        std::to_string(pairs_.count()) + ")");
    fixed_[static_cast<std::size_t>(i)] = 1;
  }
}

template <int D>
void TotalLagrangianSph<D>::clamp(Vector& field) const {
  for (Index i = 0; i < pairs_.count(); ++i)
    if (fixed_[static_cast<std::size_t>(i)]) field.segment<D>(i * D).setZero();
}

template <int D>
void TotalLagrangianSph<D>::deformation(const Real* u) {
  const Index n = pairs_.count();
  const Real lambda = options_.material.lambda(), mu = options_.material.mu();
#pragma omp parallel for if (n > kParallelParticles) schedule(static)
  for (Index i = 0; i < n; ++i) {
    const Eigen::Map<const Vec<D>> ui(u + i * D);
    Mat<D> moment = Mat<D>::Zero();  // sum_j V_j (u_j - u_i) grad_i W_ij^T
    for (Index p = pairs_.offsets[static_cast<std::size_t>(i)]; p < pairs_.offsets[static_cast<std::size_t>(i) + 1];
         ++p) {
      const Index j = pairs_.neighbour[static_cast<std::size_t>(p)];
      const Eigen::Map<const Vec<D>> g(pairs_.gradient.data() + p * D);
      moment.noalias() += pairs_.volume[static_cast<std::size_t>(j)] * (Eigen::Map<const Vec<D>>(u + j * D) - ui) * g.transpose();
    }
    const Mat<D>& B = pairs_.correction[static_cast<std::size_t>(i)];
    const Mat<D> G = moment * B.transpose();
    const Mat<D> F = Mat<D>::Identity() + G;
    const Mat<D> green = 0.5 * (F.transpose() * F - Mat<D>::Identity());
    Mat<D> S = 2 * mu * green;
    S.diagonal().array() += lambda * green.trace();
    displacementGradient_[static_cast<std::size_t>(i)] = G;
    stressTimesCorrection_[static_cast<std::size_t>(i)] = F * S * B;
  }
}

template <int D>
void TotalLagrangianSph<D>::acceleration(Real, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector>,
                                         Eigen::Ref<Vector> a) {
  deformation(u.data());
  const Index n = pairs_.count();
  const Real inverseRho = 1 / options_.material.density();
  const Real hourglass = options_.hourglassFactor * options_.material.youngsModulus();
  const Real* U = u.data();
  const Real* X = pairs_.X.data();
#pragma omp parallel for if (n > kParallelParticles) schedule(static)
  for (Index i = 0; i < n; ++i) {
    Vec<D> force = Vec<D>::Zero();
    Vec<D> penalty = Vec<D>::Zero();
    if (!fixed_[static_cast<std::size_t>(i)]) {
      const Mat<D>& PBi = stressTimesCorrection_[static_cast<std::size_t>(i)];
      const Mat<D>& Gi = displacementGradient_[static_cast<std::size_t>(i)];
      const Eigen::Map<const Vec<D>> ui(U + i * D), Xi(X + i * D);
      for (Index p = pairs_.offsets[static_cast<std::size_t>(i)];
           p < pairs_.offsets[static_cast<std::size_t>(i) + 1]; ++p) {
        const Index j = pairs_.neighbour[static_cast<std::size_t>(p)];
        const auto k = static_cast<std::size_t>(j);
        const Eigen::Map<const Vec<D>> g(pairs_.gradient.data() + p * D);
        const Real Vj = pairs_.volume[k];
        force.noalias() += Vj * ((PBi + stressTimesCorrection_[k]) * g);
        if (hourglass > 0) {
          const Vec<D> Xji = Eigen::Map<const Vec<D>>(X + j * D) - Xi;
          const Real w = g.dot(Xji) / Xji.squaredNorm();  // grad_i W_ij = w_ij (X_j - X_i)
          const Vec<D> du = Eigen::Map<const Vec<D>>(U + j * D) - ui;
          penalty.noalias() += (Vj * w) * (2 * du - (Gi + displacementGradient_[k]) * Xji);  // r_ij - r_ji
        }
      }
    }
    const Vec<D> acceleration = inverseRho * (force + hourglass * penalty);
    for (int c = 0; c < D; ++c) a[i * D + c] = acceleration[c];
  }
  if (!a.allFinite()) {
    for (Index i = 0; i < n; ++i)
      if (!a.segment<D>(i * D).allFinite())
        throw InstabilityError("total-Lagrangian SPH: non-finite acceleration at particle " + std::to_string(i), -1,
                               0, static_cast<long>(i));
  }
}

template <int D>
TotalLagrangianSphEnergy TotalLagrangianSph<D>::energy(const Vector& u, const Vector& v) {
  deformation(u.data());
  const Index n = pairs_.count();
  const Real rho = options_.material.density();
  const Real lambda = options_.material.lambda(), mu = options_.material.mu();
  const Real hourglass = options_.hourglassFactor * options_.material.youngsModulus();
  TotalLagrangianSphEnergy e;
  for (Index i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Real Vi = pairs_.volume[k];
    e.kinetic += 0.5 * rho * Vi * v.segment<D>(i * D).squaredNorm();
    const Mat<D>& G = displacementGradient_[k];
    const Mat<D> F = Mat<D>::Identity() + G;
    const Mat<D> green = 0.5 * (F.transpose() * F - Mat<D>::Identity());
    e.strain += Vi * (0.5 * lambda * green.trace() * green.trace() + mu * green.squaredNorm());
    if (hourglass > 0) {
      Real sum = 0;
      for (Index p = pairs_.offsets[k]; p < pairs_.offsets[k + 1]; ++p) {
        const Index j = pairs_.neighbour[static_cast<std::size_t>(p)];
        const Eigen::Map<const Vec<D>> g(pairs_.gradient.data() + p * D);
        const Vec<D> Xji = Eigen::Map<const Vec<D>>(pairs_.X.data() + j * D) -
                           Eigen::Map<const Vec<D>>(pairs_.X.data() + i * D);
        const Real w = g.dot(Xji) / Xji.squaredNorm();
        const Vec<D> r = u.segment<D>(j * D) - u.segment<D>(i * D) - G * Xji;
        sum += pairs_.volume[static_cast<std::size_t>(j)] * w * r.squaredNorm();
      }
      e.hourglass += 0.5 * hourglass * Vi * sum;
    }
  }
  return e;
}

template <int D>
Real TotalLagrangianSph<D>::largestFrequencySquared() {
  LinearisedAtRest<D> linear(*this, 1e-9 * smoothingLength_);
  return accelerationSpectralRadius(linear, 0, 1e-6, 2000).value;
}

template class TotalLagrangianSph<1>;
template class TotalLagrangianSph<2>;
template class TotalLagrangianSph<3>;

}  // namespace mfwave
