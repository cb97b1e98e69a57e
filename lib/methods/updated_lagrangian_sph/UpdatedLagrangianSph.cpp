// The system: owns the kernel, the skinned neighbour lists, the pair table, the constraints and the
// scratch arrays, and turns one state y into its rate. Per evaluation: refresh the lists, sum the
// densities (summation density), tabulate each pair's kernel gradient and value once (PairTable),
// the kernel-gradient corrections when asked for (a pass over the table), then the rate passes:
// configurationRate runs KinematicsPass, momentumRate ForcePass, and rhs, where both parts are
// taken at one state, the two in one sweep (FusedPass). The equations are in those files and in
// docs/theory/updated-lagrangian-sph.md.

#include "methods/updated_lagrangian_sph/UpdatedLagrangianSph.hpp"

#include "core/Error.hpp"
#include "kernels/KernelFactory.hpp"
#include "methods/updated_lagrangian_sph/ArtificialStress.hpp"
#include "methods/updated_lagrangian_sph/Diagnostics.hpp"
#include "methods/updated_lagrangian_sph/EquationOfState.hpp"
#include "methods/updated_lagrangian_sph/ForcePass.hpp"
#include "methods/updated_lagrangian_sph/FusedPass.hpp"
#include "methods/updated_lagrangian_sph/HistoryRate.hpp"
#include "methods/updated_lagrangian_sph/KernelGradientCorrection.hpp"
#include "methods/updated_lagrangian_sph/KinematicsPass.hpp"
#include "methods/updated_lagrangian_sph/OptionsValidation.hpp"
#include "methods/updated_lagrangian_sph/PairTable.hpp"
#include "methods/updated_lagrangian_sph/ParallelThreshold.hpp"
#include "methods/updated_lagrangian_sph/SkinnedNeighbours.hpp"
#include "methods/updated_lagrangian_sph/StressVoigt.hpp"
#include "methods/updated_lagrangian_sph/SummationDensity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace mfwave {
namespace {

enum class Constraint : std::uint8_t { Free, Fixed, Prescribed };

template <int D>
std::string describePosition(const Real* x) {
  std::ostringstream s;
  s << "(";
  for (int a = 0; a < D; ++a) s << (a > 0 ? ", " : "") << x[a];
  s << ")";
  return s.str();
}

template <int D>
[[noreturn]] void throwNonFinite(const char* what, Index i, const Real* x, Real t) {
  std::ostringstream s;
  s << "updated-Lagrangian SPH: non-finite " << what << " at particle " << i << " (x = " << describePosition<D>(x)
    << ") at t = " << t;
  throw InstabilityError(s.str(), -1, t, static_cast<long>(i));
}

void checkParticleIndices(const std::vector<Index>& particles, Index count) {
  for (Index i : particles)
    if (i < 0 || i >= count)
      throw InputError("particles", "index " + std::to_string(i) + " is not a particle (there are " +
                                        std::to_string(count) + ")");
}

}  // namespace

template <int D>
struct UpdatedLagrangianSph<D>::Impl {
  struct PrescribedGroup {
    Vec<D> velocity;
    TimeFunction history;
  };
  struct TractionGroup {
    std::vector<Index> particles;
    Vec<D> traction;
    TimeFunction history;
    Real area;
  };

  Impl(const UpdatedLagrangianSph& owner, std::unique_ptr<Kernel> k, Real dp, const Vector& positions)
      : system(owner),
        kernel(std::move(k)),
        neighbours(kernel->supportRadius(), owner.options_.neighbourSkin),
        spacing(dp),
        initialPositions(positions) {
    if (owner.options_.interacts) neighbours.setPairFilter(owner.options_.interacts);
    const Index n = owner.layout_.particles;
    const Material& material = owner.options_.material;
    eos.rho0 = material.density();
    eos.c0Squared = material.bulkModulus() / material.density();
    eos.gamma = owner.options_.gamma;
    const ArtificialViscosityOptions& av = owner.options_.viscosity;
    viscosity = {av.alpha, av.beta, kernel->smoothingLength(),
                 av.eta * av.eta * kernel->smoothingLength() * kernel->smoothingLength()};
    const ArtificialStressOptions& as = owner.options_.artificialStress;
    const Real referenceSpacing = as.referenceSpacing > 0 ? as.referenceSpacing : dp;
    const Real referenceKernel = kernel->value(referenceSpacing);
    if (as.enabled && !(referenceKernel > 0))
      throw InputError("method.artificial_stress_spacing", "must lie inside the kernel support");
    inverseReferenceKernel = referenceKernel > 0 ? 1 / referenceKernel : 0.0;
    for (int a = 0; a < D; ++a) bodyForce[a] = owner.options_.bodyForce[static_cast<std::size_t>(a)];
    constraint.assign(static_cast<std::size_t>(n), Constraint::Free);
    prescribedGroup.assign(static_cast<std::size_t>(n), -1);
    const auto count = static_cast<std::size_t>(n);
    summedDensity.resize(count);
    volume.resize(count);
    correction.resize(owner.options_.kernelGradientCorrection ? count : 0);
    stressOverRho2.resize(count);
    correctedStressOverRho2.resize(owner.options_.kernelGradientCorrection ? count : 0);
    artificialStress.resize(owner.options_.artificialStress.enabled ? count : 0);
    pressureOverRho2.resize(count);
    soundSpeed.resize(count);
    pairAcceleration.resize(count * D);
    energyRate.resize(count);
    viscousPower.resize(count);
    artificialStressPower.resize(count);
    largestMu.assign(count, 0.0);
    accelerationNorm.assign(count, 0.0);
    loadPower.resize(count);
    load.resize(count);
    neighbours.refresh(initialPositions.data(), n);
  }

  // The view of y with neighbour lists made valid for its positions and current densities.
  ParticleView<D> view(const Real* y) {
    if (neighbours.refresh(y + system.layout_.positionOffset(), system.layout_.particles)) pairs.rowsValid = false;
    ParticleView<D> v = constView(y);
    if (system.options_.density == DensityUpdate::Summation) {
      summationDensity(v, summedDensity.data());  // Li eq. (17); the state's rho entries are not used
      v.rho = summedDensity.data();
    }
    return v;
  }

  // view(y) with the pair table of this evaluation (the XSPH and artificial-stress weights only
  // when those are on) and the kernel-gradient corrections when the options ask for them: what the rate
  // passes use (the diagnostics do not need them).
  ParticleView<D> rateView(const Real* y) {
    ParticleView<D> v = view(y);
    const UpdatedLagrangianSphOptions& options = system.options_;
    PairTableSettings settings;
    settings.rho = v.rho;
    settings.xsph = options.xsph > 0;
    settings.artificialStress = options.artificialStress.enabled;
    settings.inverseReferenceKernel = inverseReferenceKernel;
    settings.artificialStressExponent = options.artificialStress.exponent;
    buildPairTable<D>(*kernel, neighbours.list(), v.x, v.count, settings, pairs);
    v.pairs = &pairs;
    for (Index i = 0; i < v.count; ++i) volume[static_cast<std::size_t>(i)] = v.m[i] / v.rho[i];
    v.volume = volume.data();
    if (options.kernelGradientCorrection) {
      kernelGradientCorrection(v, correction.data());
      v.correction = correction.data();
    }
    return v;
  }

  // The view of y over the lists of the last evaluation, densities from y (continuity) or unset.
  ParticleView<D> constView(const Real* y) const {
    const auto& layout = system.layout_;
    ParticleView<D> v;
    v.count = layout.particles;
    v.kernel = kernel.get();
    v.neighbours = &neighbours.list();
    v.x = y + layout.positionOffset();
    v.v = y + layout.velocityOffset();
    v.s = y + layout.stressOffset();
    v.rho = y + layout.densityOffset();
    v.m = system.mass_.data();
    return v;
  }

  // Current densities for const accessors: y's own (continuity), or summed over the last lists at
  // y's positions into a scratch array (so the pointer is valid until the next call).
  const Real* currentDensities(const Real* y) const {
    ParticleView<D> v = constView(y);
    if (system.options_.density != DensityUpdate::Summation) return v.rho;
    densityScratch.resize(static_cast<std::size_t>(v.count));
    summationDensity(v, densityScratch.data());
    return densityScratch.data();
  }

  KinematicsSettings kinematicsSettings() const {
    const UpdatedLagrangianSphOptions& options = system.options_;
    KinematicsSettings settings;
    settings.shearModulus = options.material.mu();
    settings.xsph = options.xsph;
    settings.continuity = options.density == DensityUpdate::Continuity;
    return settings;
  }

  void configurationRate(Real t, const ParticleView<D>& v, Real* qdot) {
    kinematicsRates(v, kinematicsSettings(), system.layout_, qdot, pairSums);
    finishConfigurationRate(t, v, qdot);
  }

  // pdot points at the momentum part (layout.velocityOffset() is its entry 0).
  void momentumRate(Real t, const ParticleView<D>& v, const Real* y, Real* pdot) {
    prepareStresses(v, y + system.layout_.energyOffset());
    forceRates(v, forceInputs(), forceOutputs(), pairSums);
    finishMomentumRate(t, v, pdot);
  }

  // Both parts at one state, the two pair passes in one sweep (FusedPass.hpp).
  void rate(Real t, const ParticleView<D>& v, const Real* y, Real* ydot) {
    prepareStresses(v, y + system.layout_.energyOffset());
    fusedRates(v, kinematicsSettings(), system.layout_, ydot, forceInputs(), forceOutputs(), pairSums);
    finishConfigurationRate(t, v, ydot);
    finishMomentumRate(t, v, ydot + system.layout_.configurationSize());
  }

  // The constraints on the configuration rate and the finiteness check.
  void finishConfigurationRate(Real t, const ParticleView<D>& v, Real* qdot) const {
    const auto& layout = system.layout_;
    constexpr int S = Layout::stressComponents;
    for (Index i = 0; i < layout.particles; ++i) {
      const Constraint kind = constraint[static_cast<std::size_t>(i)];
      // Clamped particles stay put; prescribed ones move with their (integrated) velocity, no XSPH.
      if (kind != Constraint::Free)
        for (int a = 0; a < D; ++a) qdot[layout.position(i, a)] = kind == Constraint::Fixed ? 0.0 : v.v[i * D + a];
      bool finite = std::isfinite(qdot[layout.density(i)]);
      for (int c = 0; c < S; ++c) finite = finite && std::isfinite(qdot[layout.stress(i, c)]);
      if (!finite) throwNonFinite<D>("stress rate", i, v.x + i * D, t);
    }
  }

  ForceInputs<D> forceInputs() const {
    const UpdatedLagrangianSphOptions& options = system.options_;
    ForceInputs<D> inputs;
    inputs.stressOverRho2 = stressOverRho2.data();
    inputs.correctedStressOverRho2 = options.kernelGradientCorrection ? correctedStressOverRho2.data() : nullptr;
    inputs.pressureOverRho2 = pressureOverRho2.data();
    inputs.soundSpeed = soundSpeed.data();
    inputs.artificialStress = options.artificialStress.enabled ? artificialStress.data() : nullptr;
    inputs.viscosity = viscosity;
    return inputs;
  }

  ForceOutputs<D> forceOutputs() {
    ForceOutputs<D> outputs;
    outputs.acceleration = pairAcceleration.data();
    outputs.energyRate = energyRate.data();
    outputs.viscousPower = viscousPower.data();
    outputs.artificialStressPower = artificialStressPower.data();
    outputs.largestMu = largestMu.data();
    return outputs;
  }

  // The accelerations and energy rates from the force pass's pair sums, with loads, body force and
  // constraints, the finiteness check and the ledger rates. pdot as in momentumRate.
  void finishMomentumRate(Real t, const ParticleView<D>& v, Real* pdot) {
    const auto& layout = system.layout_;
    const Index n = layout.particles;
    const Index base = layout.velocityOffset();

    // Loads: tractions (force traction * history * area) and the body force g.
    std::fill(load.begin(), load.end(), Vec<D>::Zero());
    for (const TractionGroup& group : tractions) {
      const Vec<D> force = group.traction * (group.history(t) * group.area);
      for (Index i : group.particles) load[static_cast<std::size_t>(i)] += force;
    }
    historyRates.resize(prescribed.size());
    for (std::size_t g = 0; g < prescribed.size(); ++g) historyRates[g] = historyRate(prescribed[g].history, t);

    for (Index i = 0; i < n; ++i) {
      const auto k = static_cast<std::size_t>(i);
      const Real m = v.m[i];
      const Vec<D> vi = v.velocity(i);
      const Vec<D> computed = Eigen::Map<const Vec<D>>(pairAcceleration.data() + i * D) + bodyForce + load[k] / m;
      Vec<D> acceleration = computed;
      Real power = (load[k] + m * bodyForce).dot(vi);
      if (constraint[k] != Constraint::Free) {
        acceleration = constraint[k] == Constraint::Fixed
                           ? Vec<D>::Zero()
                           : Vec<D>(prescribed[static_cast<std::size_t>(prescribedGroup[k])].velocity *
                                    historyRates[static_cast<std::size_t>(prescribedGroup[k])]);
        power += m * (acceleration - computed).dot(vi);  // the power of the constraint reaction
      }
      loadPower[k] = power;
      for (int a = 0; a < D; ++a) pdot[layout.velocity(i, a) - base] = acceleration[a];
      pdot[layout.energy(i) - base] = energyRate[k];
      accelerationNorm[k] = acceleration.norm();
      if (!acceleration.allFinite()) throwNonFinite<D>("acceleration", i, v.x + i * D, t);
      if (!std::isfinite(energyRate[k])) throwNonFinite<D>("energy rate", i, v.x + i * D, t);
    }
    // Ledger rates, summed in index order (independent of the thread count).
    Real loadWork = 0, viscous = 0, artificial = 0;
    for (Index i = 0; i < n; ++i) {
      const auto k = static_cast<std::size_t>(i);
      loadWork += loadPower[k];
      viscous += viscousPower[k];
      artificial += artificialStressPower[k];
    }
    pdot[layout.ledger(Layout::LoadWork) - base] = loadWork;
    pdot[layout.ledger(Layout::ViscousDissipation) - base] = viscous;
    pdot[layout.ledger(Layout::ArtificialStressWork) - base] = artificial;
    haveForces = true;
  }

  // Per particle: p (eq. 20), c (eq. 21), sigma / rho^2 with sigma = s - p I (eq. 28), p / rho^2,
  // the artificial stress R_i and, with the correction, (sigma / rho^2) C_i. They depend on the
  // state only (and on C_i of this evaluation), not on any rate.
  void prepareStresses(const ParticleView<D>& v, const Real* e) {
    constexpr int S = Layout::stressComponents;
    const Index n = v.count;
    const bool corrected = v.correction != nullptr;
    const bool withArtificialStress = system.options_.artificialStress.enabled;
    const Real epsilon = system.options_.artificialStress.epsilon;
#pragma omp parallel for if (n > kParallelParticles) schedule(static)
    for (Index i = 0; i < n; ++i) {
      const auto k = static_cast<std::size_t>(i);
      const Real rho = v.rho[i];
      const Real p = eos.pressure(rho, e[i]);
      Mat<D> sigma = stressFromVoigt<D>(v.s + i * S);
      sigma.diagonal().array() -= p;
      const Real inverseRho2 = 1 / (rho * rho);
      stressOverRho2[k] = inverseRho2 * sigma;
      pressureOverRho2[k] = p * inverseRho2;
      soundSpeed[k] = eos.soundSpeed(rho, e[i]);
      if (withArtificialStress) artificialStress[k] = artificialStressTensor<D>(sigma, rho, epsilon);
      if (corrected) correctedStressOverRho2[k] = stressOverRho2[k] * v.correction[i];
    }
  }

  const UpdatedLagrangianSph& system;
  std::unique_ptr<Kernel> kernel;
  SkinnedNeighbours<D> neighbours;
  PairTable pairs;  // the pairs inside the support and their kernel terms, of the last rate evaluation
  Real spacing;
  Vector initialPositions;  // N D, particle-major
  StiffenedGasEos eos;
  ArtificialViscosity viscosity;
  Real inverseReferenceKernel = 0;
  Vec<D> bodyForce = Vec<D>::Zero();

  std::vector<Constraint> constraint;
  std::vector<Index> prescribedGroup;  // index into prescribed, or -1
  std::vector<PrescribedGroup> prescribed;
  std::vector<TractionGroup> tractions;

  // Scratch of one evaluation.
  std::vector<Real> summedDensity;  // summation densities of the last evaluation
  std::vector<Real> volume;         // m_i / rho_i of the last rate evaluation
  std::vector<Mat<D>> correction;   // kernel-gradient corrections C_i of the last evaluation
  std::vector<Mat<D>> stressOverRho2;
  std::vector<Mat<D>> correctedStressOverRho2;  // A_i C_i, with the correction only
  std::vector<Mat<D>> artificialStress;
  std::vector<Real> pressureOverRho2;
  std::vector<Real> soundSpeed;
  std::vector<Real> pairAcceleration;
  std::vector<PairSums<D>> pairSums;  // the rate passes' per-particle pair sums (PairSweep.hpp)
  std::vector<Real> energyRate;
  std::vector<Real> viscousPower;
  std::vector<Real> artificialStressPower;
  std::vector<Real> loadPower;
  std::vector<Vec<D>> load;  // traction force per particle
  std::vector<Real> historyRates;  // per prescribed group
  mutable std::vector<Real> densityScratch;  // currentDensities' summation densities
  // Kept from the last momentum evaluation for stableStep.
  std::vector<Real> largestMu;
  std::vector<Real> accelerationNorm;
  bool haveForces = false;
};

template <int D>
UpdatedLagrangianSph<D>::UpdatedLagrangianSph(const ParticleSet<D>& particles, UpdatedLagrangianSphOptions options)
    : options_(std::move(options)) {
  validateUpdatedLagrangianSphOptions(options_);
  if (particles.ghostCount() > 0)
    throw InputError("particles", "ghost particles are not supported: the updated-Lagrangian SPH has free surfaces "
                                  "and imposes boundary conditions by constraints and tractions");
  const Index n = particles.physicalCount();
  if (n == 0) throw InputError("particles", "no physical particles");
  layout_.particles = n;
  mass_.resize(static_cast<std::size_t>(n));
  Real totalVolume = 0;
  Vector positions(n * D);
  for (Index i = 0; i < n; ++i) {
    const Real volume = particles.volume[static_cast<std::size_t>(i)];
    if (!(volume > 0) || !std::isfinite(volume))
      throw InputError("particles", "particle " + std::to_string(i) + " has a non-positive volume");
    mass_[static_cast<std::size_t>(i)] = options_.material.density() * volume;
    totalVolume += volume;
    positions.segment<D>(i * D) = particles.position(i);
  }
  // The initial spacing: the D-th root of the mean volume (exact for a lattice).
  const Real spacing = std::pow(totalVolume / static_cast<Real>(n), 1.0 / D);
  impl_ = std::make_unique<Impl>(*this, makeKernel(options_.kernel, D, options_.smoothingLengthRatio * spacing),
                                 spacing, positions);
}

template <int D>
UpdatedLagrangianSph<D>::~UpdatedLagrangianSph() = default;

template <int D>
Real UpdatedLagrangianSph<D>::smoothingLength() const {
  return impl_->kernel->smoothingLength();
}

template <int D>
Real UpdatedLagrangianSph<D>::initialSpacing() const {
  return impl_->spacing;
}

template <int D>
void UpdatedLagrangianSph<D>::fixParticles(const std::vector<Index>& particles) {
  checkParticleIndices(particles, layout_.particles);
  for (Index i : particles) {
    impl_->constraint[static_cast<std::size_t>(i)] = Constraint::Fixed;
    impl_->prescribedGroup[static_cast<std::size_t>(i)] = -1;
  }
}

template <int D>
void UpdatedLagrangianSph<D>::prescribeVelocity(const std::vector<Index>& particles, const Vec<D>& velocity,
                                                TimeFunction history) {
  checkParticleIndices(particles, layout_.particles);
  if (!velocity.allFinite()) throw InputError("velocity", "must be finite");
  const auto group = static_cast<Index>(impl_->prescribed.size());
  impl_->prescribed.push_back({velocity, std::move(history)});
  for (Index i : particles) {
    impl_->constraint[static_cast<std::size_t>(i)] = Constraint::Prescribed;
    impl_->prescribedGroup[static_cast<std::size_t>(i)] = group;
  }
}

template <int D>
void UpdatedLagrangianSph<D>::addTraction(const std::vector<Index>& particles, const Vec<D>& traction,
                                          TimeFunction history, Real area) {
  checkParticleIndices(particles, layout_.particles);
  if (!traction.allFinite()) throw InputError("traction", "must be finite");
  if (!(area > 0) || !std::isfinite(area)) throw InputError("area", "must be positive and finite");
  impl_->tractions.push_back({particles, traction, std::move(history), area});
}

template <int D>
Vector UpdatedLagrangianSph<D>::initialState(const Vector& velocity) const {
  const Index n = layout_.particles;
  if (velocity.size() != 0 && velocity.size() != n * D)
    throw InputError("velocity", "needs " + std::to_string(n * D) + " entries (N D), got " +
                                     std::to_string(velocity.size()));
  Vector y = Vector::Zero(size());
  y.segment(layout_.positionOffset(), n * D) = impl_->initialPositions;
  y.segment(layout_.densityOffset(), n).setConstant(options_.material.density());
  if (velocity.size() != 0) y.segment(layout_.velocityOffset(), n * D) = velocity;
  for (Index i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (impl_->constraint[k] == Constraint::Free) continue;
    Vec<D> v = Vec<D>::Zero();
    if (impl_->constraint[k] == Constraint::Prescribed) {
      const auto& group = impl_->prescribed[static_cast<std::size_t>(impl_->prescribedGroup[k])];
      v = group.velocity * group.history(0);
    }
    for (int a = 0; a < D; ++a) y[layout_.velocity(i, a)] = v[a];
  }
  return y;
}

template <int D>
void UpdatedLagrangianSph<D>::configurationRate(Real t, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> qdot) {
  const ParticleView<D> view = impl_->rateView(y.data());
  impl_->configurationRate(t, view, qdot.data());
}

template <int D>
void UpdatedLagrangianSph<D>::momentumRate(Real t, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> pdot) {
  const ParticleView<D> view = impl_->rateView(y.data());
  impl_->momentumRate(t, view, y.data(), pdot.data());
}

template <int D>
void UpdatedLagrangianSph<D>::rhs(Real t, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> ydot) {
  // One neighbour refresh, density summation, pair table and correction for both parts, and one
  // sweep over the pairs.
  const ParticleView<D> view = impl_->rateView(y.data());
  impl_->rate(t, view, y.data(), ydot.data());
}

template <int D>
void UpdatedLagrangianSph<D>::saveState(StateArchive& archive) const {
  StateArchive skin = archive.section("skin");
  impl_->neighbours.saveState(skin);
  archive.put("largest_mu", impl_->largestMu);
  archive.put("acceleration_norm", impl_->accelerationNorm);
  archive.putScalar("have_forces", impl_->haveForces ? 1 : 0);
}

template <int D>
void UpdatedLagrangianSph<D>::restoreState(const StateArchive& archive) {
  const std::vector<Real>& largestMu = archive.get("largest_mu");
  const std::vector<Real>& accelerationNorm = archive.get("acceleration_norm");
  const auto n = static_cast<std::size_t>(layout_.particles);
  if (largestMu.size() != n || accelerationNorm.size() != n)
    throw InputError("--restart", "the checkpoint's updated-Lagrangian SPH has " + std::to_string(largestMu.size()) +
                                      " particles, this run " + std::to_string(n));
  impl_->neighbours.restoreState(archive.section("skin"));
  impl_->pairs.rowsValid = false;
  if (impl_->neighbours.list().rowCount() != layout_.particles)
    throw InputError("--restart", "the checkpoint's neighbour lists are not of this run's particles");
  impl_->largestMu = largestMu;
  impl_->accelerationNorm = accelerationNorm;
  impl_->haveForces = archive.scalar("have_forces") != 0;
}

template <int D>
Real UpdatedLagrangianSph<D>::stableStep(const Vector& y) const {
  if (!impl_->haveForces)
    throw Error("UpdatedLagrangianSph::stableStep: no momentum evaluation yet, so no viscous or force criterion; "
                "call evaluateStepCriteria(t, y) first");
  const Real* rho = impl_->currentDensities(y.data());
  const Real h = smoothingLength();
  const Real alpha = options_.viscosity.alpha;
  const Real beta = options_.viscosity.beta;
  const Real shear = options_.material.mu();
  Real courantStep = std::numeric_limits<Real>::infinity();
  Real largestAcceleration = 0;
  for (Index i = 0; i < layout_.particles; ++i) {
    const auto k = static_cast<std::size_t>(i);
    // The signal speed of the solid: the EOS sound speed (eq. 21) stiffened by the shear modulus,
    // c_p = sqrt(c^2 + 4G / (3 rho)); with the EOS speed alone a step could outrun the P wave.
    const Real c0 = impl_->eos.soundSpeed(rho[k], y[layout_.energy(i)]);
    const Real c = std::sqrt(c0 * c0 + 4 * shear / (3 * rho[k]));
    courantStep = std::min(courantStep, h / (c + 1.2 * (alpha * c + beta * impl_->largestMu[k])));
    largestAcceleration = std::max(largestAcceleration, impl_->accelerationNorm[k]);
  }
  Real step = options_.courant * courantStep;
  if (impl_->haveForces && largestAcceleration > 0)
    step = std::min(step, options_.forceFactor * std::sqrt(h / largestAcceleration));
  return step;
}

template <int D>
Real UpdatedLagrangianSph<D>::evaluateStepCriteria(Real t, const Vector& y) {
  Vector ydot(layout_.size());
  rhs(t, y, ydot);
  return stableStep(y);
}

template <int D>
UpdatedLagrangianSphEnergy UpdatedLagrangianSph<D>::energy(const Vector& y) const {
  ParticleView<D> view = impl_->constView(y.data());
  view.rho = impl_->currentDensities(y.data());
  UpdatedLagrangianSphEnergy result =
      stateEnergy(view, y.data() + layout_.energyOffset(), impl_->eos, options_.material.mu());
  result.loadWork = y[layout_.ledger(Layout::LoadWork)];
  result.viscousDissipation = y[layout_.ledger(Layout::ViscousDissipation)];
  result.artificialStressWork = y[layout_.ledger(Layout::ArtificialStressWork)];
  return result;
}

template <int D>
ZeroEnergyModeIndicator UpdatedLagrangianSph<D>::zeroEnergyModes(const Vector& y) {
  const ParticleView<D> view = impl_->view(y.data());
  return zeroEnergyModeIndicator(view, impl_->spacing);
}

template <int D>
Real UpdatedLagrangianSph<D>::density(const Vector& y, Index i) const {
  if (options_.density == DensityUpdate::Continuity) return y[layout_.density(i)];
  return summationDensityOf(impl_->constView(y.data()), i);
}

template <int D>
Real UpdatedLagrangianSph<D>::pressure(const Vector& y, Index i) const {
  return impl_->eos.pressure(density(y, i), y[layout_.energy(i)]);
}

template <int D>
Mat<D> UpdatedLagrangianSph<D>::stress(const Vector& y, Index i) const {
  Mat<D> sigma = stressFromVoigt<D>(y.data() + layout_.stress(i, 0));
  sigma.diagonal().array() -= pressure(y, i);  // Li eq. (28)
  return sigma;
}

template <int D>
const NeighbourList& UpdatedLagrangianSph<D>::neighbours() const {
  return impl_->neighbours.list();
}

template <int D>
Real UpdatedLagrangianSph<D>::meanNeighbourCount() const {
  return impl_->neighbours.list().meanCount();
}

template <int D>
long UpdatedLagrangianSph<D>::neighbourRebuilds() const {
  return impl_->neighbours.rebuilds();
}

template class UpdatedLagrangianSph<1>;
template class UpdatedLagrangianSph<2>;
template class UpdatedLagrangianSph<3>;

}  // namespace mfwave
