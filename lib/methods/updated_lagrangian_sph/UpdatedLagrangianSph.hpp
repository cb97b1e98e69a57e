#pragma once
// Updated-Lagrangian SPH for elastic solids (primer by Li, eqs. 17-30; docs/references.md) as a split
// first-order system y' = F(t, y) over moving particles; the state layout is in
// UpdatedLagrangianSphLayout.hpp. One evaluation of F:
//   density       eq. (17) summation or eq. (18) continuity
//   pressure      eq. (20) stiffened gas (gamma = 1: isothermal), sound speed eq. (21)
//   kinematics    eq. (22) velocity gradient, eq. (24) strain rate, eq. (25) spin
//   stress rate   eq. (26) Jaumann hypoelasticity; sigma = s - p I, eq. (28)
//   energy        eq. (29), with Monaghan's artificial viscosity Pi_ij
//   momentum      eq. (30), with Pi_ij and the Monaghan-Gray artificial stress R_ij
//   positions     dx/dt = v, optionally XSPH
// Constraints (clamped particles, prescribed velocities) and surface tractions are opt-in.
//
// The system owns its neighbour search (a cell list with a skin, rebuilt only when particles have
// moved far enough), so integrators stay ignorant of particles. Methods never step time and never
// write files: the energy ledger, the zero-energy-mode indicator and the field accessors are read by
// the driver's observers.

#include "core/TimeFunction.hpp"
#include "core/Types.hpp"
#include "methods/updated_lagrangian_sph/UpdatedLagrangianSphLayout.hpp"
#include "methods/updated_lagrangian_sph/UpdatedLagrangianSphOptions.hpp"
#include "neighbours/NeighbourList.hpp"
#include "particles/ParticleSet.hpp"
#include "systems/SplitFirstOrderSystem.hpp"

#include <memory>
#include <vector>

namespace mfwave {

// The energy balance of one state. With no artificial terms and no loads,
// kinetic + internal stays constant up to time-integration error, and internal equals strain.
struct UpdatedLagrangianSphEnergy {
  Real kinetic = 0;               // sum 1/2 m |v|^2
  Real strain = 0;                // elastic energy stored in the stress and the density
  Real internal = 0;              // sum m e (eq. 29 integrated)
  Real loadWork = 0;              // work done on the body by tractions, body forces and constraints
  Real viscousDissipation = 0;    // energy removed by Pi_ij (>= 0)
  Real artificialStressWork = 0;  // work done by R_ij
  // kinetic + internal - loadWork: conserved by the continuous-time scheme.
  Real balance() const { return kinetic + internal - loadWork; }
};

// How far the particle field is from smooth: the signs users see when the tensile instability or
// zero-energy (hourglass, zig-zag) modes start.
struct ZeroEnergyModeIndicator {
  // sqrt(sum m |v_i - vbar_i|^2 / sum m |v_i|^2), vbar_i the Shepard-normalised kernel average of v
  // around i: O((h k)^2) for a smooth field of wavenumber k, O(1) for a particle-scale zig-zag.
  Real zigzag = 0;
  Index zigzagWorstParticle = -1;
  // Smallest pair distance over the initial spacing: clumping (tensile instability) drives it
  // towards 0; a healthy solid stays near its initial value.
  Real minimumSpacingRatio = 0;
};

template <int D>
class UpdatedLagrangianSph : public SplitFirstOrderSystem {
 public:
  using Layout = UpdatedLagrangianSphLayout<D>;

  // Masses m_i = rho0 volume_i from the physical particles of `particles` (ghosts are rejected with
  // InputError("particles")). Throws InputError naming the option for invalid options.
  UpdatedLagrangianSph(const ParticleSet<D>& particles, UpdatedLagrangianSphOptions options);
  ~UpdatedLagrangianSph() override;

  const Layout& layout() const { return layout_; }
  const UpdatedLagrangianSphOptions& options() const { return options_; }
  Index particleCount() const { return layout_.particles; }
  Real smoothingLength() const;
  Real initialSpacing() const;
  const std::vector<Real>& masses() const { return mass_; }

  // --- Constraints and loads (set before the integrator is initialised) ---
  // Clamped: velocity and position held (v = 0). The particles still take part in every sum.
  void fixParticles(const std::vector<Index>& particles);
  // v_i(t) = velocity * history(t) on these particles (history(0) sets the initial velocity).
  void prescribeVelocity(const std::vector<Index>& particles, const Vec<D>& velocity, TimeFunction history);
  // Force traction(t) * area on each particle (area per particle, e.g. dp^(D-1)).
  void addTraction(const std::vector<Index>& particles, const Vec<D>& traction, TimeFunction history, Real area);

  // y0: positions from the particle set, rho = rho0, s = 0, e = 0, ledger 0, and velocities from
  // `velocity` (N D entries; empty means 0), overridden by constraints.
  Vector initialState(const Vector& velocity = {}) const;

  // --- SplitFirstOrderSystem ---
  Index size() const override { return layout_.size(); }
  Index configurationSize() const override { return layout_.configurationSize(); }
  void configurationRate(Real t, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> qdot) override;
  void momentumRate(Real t, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> pdot) override;
  void rhs(Real t, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> ydot) override;

  // --- FirstOrderSystem checkpoints ---
  // What an evaluation depends on beyond (t, y), and what stableStep and the diagnostics read
  // from the last evaluation: the neighbour lists (the positions they were built at and the
  // rebuild count; restored by rebuilding from those positions) and the step criteria of the last
  // momentum evaluation (largest mu_ij, acceleration norms). Everything else is scratch that the
  // next evaluation overwrites before reading. Constraints, loads and options are not saved: the
  // restarted run sets them up again from the same scene.
  void saveState(StateArchive& archive) const override;
  void restoreState(const StateArchive& archive) override;

  // The step from the CFL, viscous and force criteria at y (options courant, forceFactor). The
  // viscous signal speeds (largest mu_ij) and the force criterion's accelerations are those of the
  // last momentum evaluation, which an integrator makes at every step: the criteria are not
  // computed twice. Before any evaluation there are none, and the call is refused (Error); call
  // evaluateStepCriteria first.
  Real stableStep(const Vector& y) const;
  // Evaluates the right-hand side at (t, y) for the criteria above, then returns stableStep(y): the
  // first step of a run, before the integrator has evaluated anything.
  Real evaluateStepCriteria(Real t, const Vector& y);

  // --- Diagnostics for observers ---
  UpdatedLagrangianSphEnergy energy(const Vector& y) const;
  ZeroEnergyModeIndicator zeroEnergyModes(const Vector& y);
  // Current density (the summation value in Summation mode), pressure (eq. 20) and Cauchy stress
  // sigma = s - p I (eq. 28) of particle i.
  Real density(const Vector& y, Index i) const;
  Real pressure(const Vector& y, Index i) const;
  Mat<D> stress(const Vector& y, Index i) const;
  // The neighbour lists of the last evaluation (radius (1 + skin) kappa h) and their mean length.
  const NeighbourList& neighbours() const;
  Real meanNeighbourCount() const;
  long neighbourRebuilds() const;

 private:
  struct Impl;
  Layout layout_;
  UpdatedLagrangianSphOptions options_;
  std::vector<Real> mass_;
  std::unique_ptr<Impl> impl_;
};

extern template class UpdatedLagrangianSph<1>;
extern template class UpdatedLagrangianSph<2>;
extern template class UpdatedLagrangianSph<3>;

}  // namespace mfwave
