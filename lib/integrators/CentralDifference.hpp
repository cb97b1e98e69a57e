#pragma once
// The explicit central-difference scheme u_{n+1} = 2 u_n - u_{n-1} + dt^2 a_n (Ding-Long-Wu
// eq. 23), second order, conditionally stable (w dt <= 2 for an undamped mode of frequency w).
//
// It is carried in the algebraically equivalent staggered form (u_n, v_{n-1/2}):
//   v_{n+1/2} = v_{n-1/2} + dt a_n,   u_{n+1} = u_n + dt v_{n+1/2},
// because differencing u directly loses digits (2 u_n - u_{n-1} cancels when dt is small), while the
// staggered velocity keeps the increment at full precision. Same trajectory, better round-off.
//
// Start: v_{-1/2} = v_0 - dt/2 a_0, so u_1 = u_0 + dt v_0 + dt^2/2 a_0 (the Taylor start), with
// a_0 = a(t0, u0, v0) exact.
// The reported (synchronous) velocity is v_n = v_{n-1/2} + dt/2 a_n, i.e. (v_{n-1/2} + v_{n+1/2}) / 2.
//
// Velocity-dependent accelerations (damping, dashpots), two treatments (Damping):
// - implicit (default): for a LinearOperatorSystem with damping, Ding-Long-Wu eq. (32) with the
//   centred velocity (32b): M a_n + C v_n = f(t_n) - K u_n, solved as
//   (M + dt/2 C) a_n = f(t_n) - K u_n - C v_{n-1/2} with M + dt/2 C factorised once
//   (LinearOperatorSystem::centredDamping: ImplicitDampingSolver for sparse matrices, per-type
//   blocks on a lattice). Stable for any dashpot strength (still w dt < 2 for the stiffness);
//   no acceleration() calls after the start. Other velocity-dependent systems use the predictor.
// - predictor: a_n = a(t_n, u_n, v_n*) with v_n* = v_{n-1/2} + dt/2 a_{n-1}; second order, explicit,
//   one evaluation per step, but unstable for strong dashpots (c dt / m of order 1 and more).
// Undamped systems take the plain path either way (no solve, bit-for-bit the classical scheme).
//
// Two optional hooks, each costing nothing unless set:
// - a velocity filter (conservative smoothing, Ding-Long-Wu eq. 33) applied to v_{n+1/2} right
//   after the kick and before the drift. The synchronous velocity is then built on the filtered
//   half-step velocity: v_n = v~_{n-1/2} + dt/2 a_n, the mean of the filtered v~_{n-1/2} and the
//   v_{n+1/2} the next step will filter;
// - prescribed displacements (Ding-Long-Wu eq. 30) u_{n+1}[dofs] = g(t_{n+1}) in place of the
//   update, with v_{n+1/2}[dofs] = (g_{n+1} - u_n[dofs]) / dt; the reported v and a at those dofs
//   are the central differences of g (see PrescribedDisplacement). Where both act, the prescription
//   wins. u0[dofs] must equal g(t0) (InputError "initial_displacement"); the reported state at t0 is
//   the caller's (u0, v0).

#include "integrators/FixedStepSecondOrderIntegrator.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace mfwave {

class CentredDampingSolve;
class PrescribedDisplacement;

class CentralDifference : public FixedStepSecondOrderIntegrator {
 public:
  enum class Damping { implicit, predictor };
  // Filters the half-step velocity in place (Ding-Long-Wu eq. 33); must keep its size.
  using VelocityFilter = std::function<void(Real dt, Vector& velocity)>;

  explicit CentralDifference(Damping damping = Damping::implicit);
  ~CentralDifference() override;

  std::string name() const override { return "central_difference"; }
  // Evaluates a_0 = a(t0, u0, v0) once; factorises M + dt/2 C for implicit damping; checks and
  // applies the prescribed displacements.
  void initialise(SecondOrderSystem& system, Real t0, const Vector& u0, const Vector& v0, Real dt) override;
  void step() override;

  // Configuration for the next initialise(): both throw InputError ("damping",
  // "prescribed_displacement") once initialised.
  void setDamping(Damping damping);
  // g(t, values) fills values (sized dofs.size()) with the displacements of `dofs` at t. Empty dofs
  // remove the prescription. Dofs are checked against the system at initialise().
  void setPrescribedDisplacement(std::vector<Index> dofs, std::function<void(Real t, Vector& values)> g);
  // May be set or cleared (empty function) at any time.
  void setVelocityFilter(VelocityFilter filter) { filter_ = std::move(filter); }

  Damping damping() const { return damping_; }
  // True when the bound system's damping is treated implicitly (eq. 32).
  bool implicitDamping() const { return static_cast<bool>(dampingSolver_); }
  // The scheme's own velocity v_{n-1/2}.
  const Vector& staggeredVelocity() const { return vHalf_; }

  // "implicit", "predictor" (for scene files); dampingFromName throws InputError("integrator.damping").
  static std::vector<std::string> dampingNames();
  static Damping dampingFromName(const std::string& name);

 protected:
  // v_{n-1/2} and the prescribed displacements' window (g_n, g_{n+1} and the reported v, a there).
  void saveHistory(StateArchive& archive) const override;
  void restoreHistory(const StateArchive& archive) override;

 private:
  // After the drift and the clock: a_{n+1} and the synchronous v_{n+1}.
  void closeStep();

  Damping damping_;
  VelocityFilter filter_;
  std::unique_ptr<PrescribedDisplacement> prescribed_;
  std::unique_ptr<CentredDampingSolve> dampingSolver_;  // set when implicitDamping()
  Vector vHalf_;      // v_{n-1/2}
  Vector vPredict_;   // v_n* (predictor path only)
  Vector noPrescribedAcceleration_;  // empty: the solver's argument when nothing is prescribed
};

}  // namespace mfwave
