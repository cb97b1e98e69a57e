#pragma once
// Explicit Runge-Kutta integration of a first-order system y' = F(t, y) by SUNDIALS ARKODE's
// ERKStep, with a fixed step or with error control. This adapter is the only code in mfwave that
// sees SUNDIALS: its header keeps SUNDIALS types out (pimpl), so a SUNDIALS upgrade (7.x moves
// ERKStep* to ARKode*) touches ArkodeExplicit.cpp alone.
//
// ARKODE works directly on the adapter's Eigen vector (N_VMake_Serial over its storage; for a
// system that reports a VectorDistribution, N_VMake_Parallel over the rank's share, made by the
// MPI half of this adapter, ArkodeMpiVectors.cpp, in MPI builds only), and the right-hand side is
// evaluated on Eigen::Maps of ARKODE's vectors (FirstOrderSystem::rhs takes Eigen::Ref): no copies
// between the two libraries.

#include "core/StateArchive.hpp"
#include "core/Types.hpp"
#include "systems/FirstOrderSystem.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mfwave {

struct ArkodeOptions {
  // Butcher table by name; see ArkodeExplicit::tableNames(). "classic_rk4" has no embedded
  // method and so runs with a fixed step only.
  std::string table = "classic_rk4";
  bool adaptive = false;
  Real fixedStep = 0;              // fixed mode: the step (> 0), checked at initialise
  Real relativeTolerance = 1e-6;   // adaptive mode
  Real absoluteTolerance = 1e-9;   // adaptive mode
  Real initialStep = 0;            // adaptive mode: first step; 0 lets ARKODE estimate it
  long maxStepsPerAdvance = 10000000;  // ARKODE's mxstep: steps allowed in one advanceTo
};

struct ArkodeStatistics {
  long steps = 0;           // accepted steps
  long stepAttempts = 0;    // accepted + rejected
  long rhsEvaluations = 0;  // calls of F
  long failedSteps = 0;     // steps rejected by the error test
};

// The coefficients of an explicit Butcher table (row-major s x s A, strictly lower triangular).
struct ButcherCoefficients {
  int stages = 0;
  int order = 0;
  std::vector<Real> a, b, c;
  bool embedded = false;  // has an embedding for error control
};

class ArkodeExplicit {
 public:
  // Checks the options that do not need a system: table name (InputError "integrator.table",
  // listing the valid names), an embedding for adaptive runs, tolerances.
  explicit ArkodeExplicit(ArkodeOptions options = {});
  ~ArkodeExplicit();
  ArkodeExplicit(ArkodeExplicit&&) noexcept;
  ArkodeExplicit& operator=(ArkodeExplicit&&) noexcept;
  ArkodeExplicit(const ArkodeExplicit&) = delete;
  ArkodeExplicit& operator=(const ArkodeExplicit&) = delete;

  // The names accepted in ArkodeOptions::table.
  static std::vector<std::string> tableNames();
  // The coefficients of a table by name (for stability analysis: integrators/StabilityLimit.hpp).
  // Throws InputError("integrator.table") for an unknown name.
  static ButcherCoefficients coefficients(const std::string& table);

  // Binds the system (it must outlive the integrator's use) and sets y(t0) = y0. May be called
  // again to restart.
  void initialise(FirstOrderSystem& system, Real t0, const Vector& y0);
  // One step: of the fixed size, or one internal adaptive step of the size ARKODE chooses.
  void step();
  // Advances to exactly t (>= time()); the last step is shortened to land on t.
  void advanceTo(Real t);
  // Fixed-step runs: the step of every following step (and options().fixedStep), e.g. from a CFL
  // rule before each step. May be called before initialise or between steps. Throws
  // InputError("integrator.time_step") unless h > 0 and finite, Error on an adaptive run.
  void setFixedStep(Real h);
  // Adaptive runs: an upper bound on the steps ARKODE chooses from now on (0: none); it persists
  // across initialise. Throws
  // InputError("integrator.max_step") for a negative or non-finite h, Error on a fixed-step run.
  void setMaxStep(Real h);

  // Checkpoints, fixed-step runs only: t, y, the step, the last step and the counters.
  // restoreState re-creates ARKODE's memory at (t, y) on the bound system: an explicit Runge-Kutta
  // step with a fixed size depends on nothing else, so the steps that follow are bitwise those of
  // the uninterrupted run. An adaptive run's error controller keeps a history ARKODE does not
  // expose: saveState refuses it (InputError "integrator.adaptive").
  void saveState(StateArchive& archive) const;
  void restoreState(const StateArchive& archive);

  Real time() const;
  const Vector& state() const;   // y at time()
  Real lastStepSize() const;     // 0 before the first step
  ArkodeStatistics statistics() const;
  const ArkodeOptions& options() const;
  int order() const;             // order of the method in the table
  bool isInitialised() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mfwave
