// All SUNDIALS calls of mfwave live in this file (see ArkodeExplicit.hpp), but for the making of
// MPI vectors, which only MPI builds link (ArkodeMpiVectors.cpp, ArkodeVectorHook.hpp).

#include "integrators/ArkodeExplicit.hpp"

#include "core/Error.hpp"
#include "integrators/ArkodeVectorHook.hpp"

#include <arkode/arkode_butcher_erk.h>
#include <arkode/arkode_erkstep.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace mfwave {
namespace {

// Built-in ERK tables of ARKODE 6.4.1, by the names mfwave's inputs use.
struct NamedTable {
  const char* name;
  ARKODE_ERKTableID id;
};
constexpr NamedTable kBuiltinTables[] = {
    {"heun_euler_2_1_2", ARKODE_HEUN_EULER_2_1_2},
    {"bogacki_shampine_4_2_3", ARKODE_BOGACKI_SHAMPINE_4_2_3},
    {"ark324_explicit", ARKODE_ARK324L2SA_ERK_4_2_3},
    {"zonneveld_5_3_4", ARKODE_ZONNEVELD_5_3_4},
    {"ark436_explicit", ARKODE_ARK436L2SA_ERK_6_3_4},
    {"sayfy_aburub_6_3_4", ARKODE_SAYFY_ABURUB_6_3_4},
    {"cash_karp_6_4_5", ARKODE_CASH_KARP_6_4_5},
    {"fehlberg_6_4_5", ARKODE_FEHLBERG_6_4_5},
    {"dormand_prince_7_4_5", ARKODE_DORMAND_PRINCE_7_4_5},
    {"ark548_explicit", ARKODE_ARK548L2SA_ERK_8_4_5},
    {"verner_8_5_6", ARKODE_VERNER_8_5_6},
    {"fehlberg_13_7_8", ARKODE_FEHLBERG_13_7_8},
    {"knoth_wolke_3_3", ARKODE_KNOTH_WOLKE_3_3},
    {"ark437_explicit", ARKODE_ARK437L2SA_ERK_7_3_4},
    {"ark548b_explicit", ARKODE_ARK548L2SAb_ERK_8_4_5},
};
constexpr const char* kClassicRk4 = "classic_rk4";

// The classic 4-stage RK4 (Kutta 1901), which ARKODE 6.4 does not ship: c = (0, 1/2, 1/2, 1),
// b = (1/6, 1/3, 1/3, 1/6), order 4, no embedding (so fixed step only).
ARKodeButcherTable makeClassicRk4() {
  sunrealtype c[4] = {0, 0.5, 0.5, 1};
  sunrealtype a[16] = {0,   0,   0, 0,   // row-major s x s
                       0.5, 0,   0, 0,
                       0,   0.5, 0, 0,
                       0,   0,   1, 0};
  sunrealtype b[4] = {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6};
  return ARKodeButcherTable_Create(4, 4, 0, c, a, b, nullptr);
}

std::string validNames() {
  std::string list;
  for (const auto& name : ArkodeExplicit::tableNames()) list += (list.empty() ? "" : ", ") + name;
  return list;
}

// SUNDIALS 6.4.1 defect: after each step ERKStep reuses the last stage's F as f(t_{n+1}, y_{n+1})
// (first same as last) whenever c[s-1] = 1, without checking that the last row of A equals b. For
// tables where it does not (classic RK4, Heun-Euler, Verner 6, Fehlberg 8) the next step then starts
// from a wrong first stage and the method drops an order (RK4 measured third order). Fixed upstream
// in 6.6 (stiffly-accurate test). When a post-processing step function is attached, ARKODE
// re-evaluates f at the start of the next step instead, so a no-op one restores the method, at no
// extra cost for these tables (they are not FSAL and need that evaluation anyway). Genuinely FSAL
// tables (Dormand-Prince, Bogacki-Shampine, the ARK ERK tables) keep their saved evaluation.
bool misdetectedAsFsal(const ARKodeButcherTable table) {
  const int s = table->stages;
  constexpr sunrealtype tiny = 1e-14;
  if (std::abs(table->c[s - 1] - 1) > tiny) return false;
  for (int j = 0; j < s; ++j)
    if (std::abs(table->A[s - 1][j] - table->b[j]) > tiny) return true;
  return false;
}

int keepStep(sunrealtype, N_Vector, void*) { return 0; }

// Far beyond any simulated time: the stop time used when none is wanted (6.4.1 has no
// ERKStepClearStopTime, and a stop time once set persists).
constexpr sunrealtype kNoStopTime = 1e300;

// Installed by enableArkodeMpiVectors (MPI builds); null: distributed systems are refused.
std::atomic<ArkodeParallelVectorMaker> parallelVectorMaker{nullptr};

}  // namespace

void setArkodeParallelVectorMaker(ArkodeParallelVectorMaker maker) { parallelVectorMaker.store(maker); }

namespace {

// The WRMS norm of a system that fixes the order of its sums (VectorDistribution::
// orderedSumOfSquares): sqrt(sum_i (x_i w_i)^2 / N) with the sum in the system's order. SUNDIALS
// calls the vector operation without user data, so the integrator is found by the vector's context
// (one per integrator).
struct OrderedNorm {
  std::function<Real(const Real*, Index)> sumOfSquares;
  Index localLength = 0;
  Real globalLength = 0;
  std::vector<Real> scratch;
};
std::mutex orderedNormsMutex;
std::map<SUNContext, OrderedNorm*> orderedNorms;

sunrealtype orderedWrmsNorm(N_Vector x, N_Vector w) {
  OrderedNorm* norm = nullptr;
  {
    const std::lock_guard<std::mutex> lock(orderedNormsMutex);
    norm = orderedNorms.at(x->sunctx);
  }
  const Real* xd = N_VGetArrayPointer(x);
  const Real* wd = N_VGetArrayPointer(w);
  norm->scratch.resize(static_cast<std::size_t>(norm->localLength));
  for (Index i = 0; i < norm->localLength; ++i) norm->scratch[static_cast<std::size_t>(i)] = xd[i] * wd[i];
  return std::sqrt(norm->sumOfSquares(norm->scratch.data(), norm->localLength) / norm->globalLength);
}

}  // namespace

struct ArkodeExplicit::Impl {
  ArkodeOptions options;
  ARKodeButcherTable table = nullptr;  // our copy; ERKStepSetTable copies it again
  SUNContext context = nullptr;
  N_Vector y = nullptr;                // wraps yData's storage (not owned by SUNDIALS); serial or MPI
  void* memory = nullptr;
  Vector yData;
  FirstOrderSystem* system = nullptr;
  Real time = 0;
  Real maxStep = 0;            // adaptive runs: setMaxStep's bound (0: none)
  ArkodeStatistics before;     // counters of the run before the checkpoint this one resumed from
  Real resumedLastStep = 0;    // the last step before that checkpoint, until a step is taken
  bool repeatedSetupEvaluation = false;  // resumed: ARKODE's set-up evaluation is not counted again
  std::exception_ptr pending;  // an exception thrown by the system inside a SUNDIALS callback
  std::string lastMessage;     // SUNDIALS's own text for the last error
  std::unique_ptr<OrderedNorm> orderedNorm;  // the system's order of the norms' sums, if it fixes one

  ~Impl() {
    release();
    if (table) ARKodeButcherTable_Free(table);
  }

  void release() {
    if (memory) ERKStepFree(&memory);
    if (context && orderedNorm) {
      const std::lock_guard<std::mutex> lock(orderedNormsMutex);
      orderedNorms.erase(context);
    }
    orderedNorm.reset();
    if (y) N_VDestroy(y);  // a vector made over user data leaves the data alone
    y = nullptr;
    if (context) SUNContext_Free(&context);
    context = nullptr;
    system = nullptr;
  }

  // Translates a SUNDIALS return flag into mfwave::Error (or rethrows what the system threw).
  void check(int flag, const char* function) {
    if (flag >= 0) return;
    if (pending) {
      std::exception_ptr e = std::exchange(pending, nullptr);
      std::rethrow_exception(e);
    }
    char* flagName = ERKStepGetReturnFlagName(flag);
    std::string what = std::string("ARKODE ") + function + " failed with flag " +
                       (flagName ? flagName : "?") + " (" + std::to_string(flag) + ")";
    std::free(flagName);
    if (!lastMessage.empty()) what += ": " + lastMessage;
    lastMessage.clear();
    throw Error(what);
  }

  static int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* userData) {
    auto* self = static_cast<Impl*>(userData);
    try {
      // This rank's length: the generic accessors serve serial and MPI vectors alike.
      const Index n = self->yData.size();
      // Views of ARKODE's storage: stage vectors are ARKODE's, not ours, and need no copy.
      Eigen::Map<const Vector> yView(N_VGetArrayPointer(y), n);
      Eigen::Map<Vector> ydotView(N_VGetArrayPointer(ydot), n);
      self->system->rhs(t, yView, ydotView);
      return 0;
    } catch (...) {
      // Exceptions must not cross SUNDIALS's C frames: keep it, fail the call, rethrow after.
      self->pending = std::current_exception();
      return -1;
    }
  }

  static void errorHandler(int code, const char* module, const char* function, char* message,
                           void* userData) {
    if (code >= 0) return;  // warnings: nothing to report through an exception
    auto* self = static_cast<Impl*>(userData);
    self->lastMessage = std::string(module ? module : "") + "::" + (function ? function : "") + ": " +
                        (message ? message : "");
  }

  // The context and y over yData: serial vectors, or, for a system that holds one rank's share
  // (FirstOrderSystem::distribution), the MPI vectors, whose dot products and norms are reduced
  // over the ranks so that every rank's error test sees the same global norm and all take the same
  // steps. Element-wise operations are the serial ones either way.
  void makeVector(const std::optional<VectorDistribution>& distribution) {
    makeSerialOrParallelVector(distribution);
    if (!distribution || !distribution->orderedSumOfSquares) return;
    // The system's order for the norms' sums: every vector ARKODE clones from y inherits the
    // operation; the fused array version is dropped so that none bypasses it.
    orderedNorm = std::make_unique<OrderedNorm>();
    orderedNorm->sumOfSquares = distribution->orderedSumOfSquares;
    orderedNorm->localLength = yData.size();
    orderedNorm->globalLength = static_cast<Real>(N_VGetLength(y));
    {
      const std::lock_guard<std::mutex> lock(orderedNormsMutex);
      orderedNorms[context] = orderedNorm.get();
    }
    y->ops->nvwrmsnorm = &orderedWrmsNorm;
    y->ops->nvwrmsnormvectorarray = nullptr;
  }

  void makeSerialOrParallelVector(const std::optional<VectorDistribution>& distribution) {
    const auto local = static_cast<sunindextype>(yData.size());
    if (!distribution || !distribution->communicator) {
      check(SUNContext_Create(nullptr, &context), "SUNContext_Create");
      y = N_VMake_Serial(local, yData.data(), context);
      if (!y) throw Error("ARKODE N_VMake_Serial failed");
      return;
    }
    const ArkodeParallelVectorMaker maker = parallelVectorMaker.load();
    if (!maker)
      throw Error("arkode: the system is distributed over MPI ranks, but this program has no MPI vectors for "
                  "ARKODE (an MPI build's mfwave::integrators_mpi, enableArkodeMpiVectors())");
    if (!distribution->communicator || distribution->globalSize < yData.size())
      throw Error("arkode: a distributed system must give its communicator and a global size of at least its "
                  "own (" + std::to_string(yData.size()) + "), got " + std::to_string(distribution->globalSize));
    // 6.4.1 takes a pointer to the communicator (kept for SUNDIALS' profiler); it does not write it.
    check(SUNContext_Create(const_cast<void*>(distribution->communicator), &context), "SUNContext_Create");
    y = maker(distribution->communicator, local, static_cast<sunindextype>(distribution->globalSize), yData.data(),
              context);
    if (!y)
      throw Error("ARKODE N_VMake_Parallel failed (do the ranks' sizes sum to the global size " +
                  std::to_string(distribution->globalSize) + "?)");
  }

  sunrealtype evolve(sunrealtype tout, int task, const char* what) {
    pending = nullptr;
    sunrealtype reached = time;
    check(ERKStepEvolve(memory, tout, y, &reached, task), what);
    return reached;
  }
};

std::vector<std::string> ArkodeExplicit::tableNames() {
  std::vector<std::string> names{kClassicRk4};
  for (const auto& table : kBuiltinTables) names.emplace_back(table.name);
  return names;
}

namespace {

// A new ARKODE table by name (the caller frees it); InputError for an unknown name.
ARKodeButcherTable loadTable(const std::string& name) {
  ARKodeButcherTable table = nullptr;
  if (name == kClassicRk4) {
    table = makeClassicRk4();
  } else {
    for (const auto& builtin : kBuiltinTables)
      if (name == builtin.name) table = ARKodeButcherTable_LoadERK(builtin.id);
    if (!table) throw InputError("integrator.table", "unknown table '" + name + "'; valid: " + validNames());
  }
  if (!table) throw Error("ARKODE could not build the Butcher table '" + name + "'");
  return table;
}

}  // namespace

ButcherCoefficients ArkodeExplicit::coefficients(const std::string& name) {
  ARKodeButcherTable table = loadTable(name);
  ButcherCoefficients out;
  out.stages = table->stages;
  out.order = table->q;
  out.embedded = table->d != nullptr;
  const auto s = static_cast<std::size_t>(table->stages);
  out.a.assign(s * s, 0);
  out.b.assign(s, 0);
  out.c.assign(s, 0);
  for (std::size_t i = 0; i < s; ++i) {
    out.b[i] = table->b[i];
    out.c[i] = table->c[i];
    for (std::size_t j = 0; j < s; ++j) out.a[i * s + j] = table->A[i][j];
  }
  ARKodeButcherTable_Free(table);
  return out;
}

ArkodeExplicit::ArkodeExplicit(ArkodeOptions options) : impl_(std::make_unique<Impl>()) {
  impl_->options = std::move(options);
  const ArkodeOptions& o = impl_->options;
  impl_->table = loadTable(o.table);
  if (o.adaptive) {
    if (impl_->table->d == nullptr)
      throw InputError("integrator.table", "'" + o.table +
                                               "' has no embedded method for error estimation, so it "
                                               "runs with a fixed step only");
    if (!(o.relativeTolerance > 0) || !std::isfinite(o.relativeTolerance))
      throw InputError("integrator.relative_tolerance", "must be positive");
    if (!(o.absoluteTolerance >= 0) || !std::isfinite(o.absoluteTolerance))
      throw InputError("integrator.absolute_tolerance", "must be non-negative");
    if (!(o.initialStep >= 0) || !std::isfinite(o.initialStep))
      throw InputError("integrator.initial_step", "must be non-negative (0: estimated)");
  }
}

ArkodeExplicit::~ArkodeExplicit() = default;
ArkodeExplicit::ArkodeExplicit(ArkodeExplicit&&) noexcept = default;
ArkodeExplicit& ArkodeExplicit::operator=(ArkodeExplicit&&) noexcept = default;

void ArkodeExplicit::initialise(FirstOrderSystem& system, Real t0, const Vector& y0) {
  Impl& m = *impl_;
  const ArkodeOptions& o = m.options;
  if (y0.size() != system.size() || y0.size() == 0)
    throw InputError("initial_state", "y0 must have the system's size " + std::to_string(system.size()) +
                                          " (> 0), got " + std::to_string(y0.size()));
  if (!o.adaptive && (!(o.fixedStep > 0) || !std::isfinite(o.fixedStep)))
    throw InputError("integrator.time_step", "a fixed-step run needs a positive step (got " +
                                                 std::to_string(o.fixedStep) + ")");
  m.release();
  m.before = {};
  m.resumedLastStep = 0;
  m.repeatedSetupEvaluation = false;
  m.yData = y0;  // from here on, yData is never resized: ARKODE holds a pointer to its storage
  m.time = t0;
  m.system = &system;

  m.makeVector(system.distribution());
  m.memory = ERKStepCreate(&Impl::rhs, t0, m.y, m.context);
  if (!m.memory) throw Error("ARKODE ERKStepCreate failed");
  m.check(ERKStepSetErrHandlerFn(m.memory, &Impl::errorHandler, &m), "ERKStepSetErrHandlerFn");
  m.check(ERKStepSetUserData(m.memory, &m), "ERKStepSetUserData");
  m.check(ERKStepSetTable(m.memory, m.table), "ERKStepSetTable");
  if (misdetectedAsFsal(m.table))
    m.check(ERKStepSetPostprocessStepFn(m.memory, &keepStep), "ERKStepSetPostprocessStepFn");
  if (o.adaptive) {
    m.check(ERKStepSStolerances(m.memory, o.relativeTolerance, o.absoluteTolerance), "ERKStepSStolerances");
    if (o.initialStep > 0) m.check(ERKStepSetInitStep(m.memory, o.initialStep), "ERKStepSetInitStep");
    if (m.maxStep > 0) m.check(ERKStepSetMaxStep(m.memory, m.maxStep), "ERKStepSetMaxStep");
  } else {
    m.check(ERKStepSetFixedStep(m.memory, o.fixedStep), "ERKStepSetFixedStep");
  }
  m.check(ERKStepSetMaxNumSteps(m.memory, o.maxStepsPerAdvance), "ERKStepSetMaxNumSteps");
}

void ArkodeExplicit::step() {
  Impl& m = *impl_;
  if (!m.memory) throw Error("arkode: step() called before initialise()");
  // A stop time set by advanceTo persists: lift it, or the next step would be clipped to nothing.
  m.check(ERKStepSetStopTime(m.memory, kNoStopTime), "ERKStepSetStopTime");
  // In one-step mode tout only gives the direction (and, adaptive without an initial step, the
  // scale for ARKODE's first-step estimate).
  Real hint = m.options.adaptive ? lastStepSize() : m.options.fixedStep;
  if (!(hint > 0)) hint = m.options.initialStep > 0 ? m.options.initialStep : std::max(Real(1), std::abs(m.time));
  m.time = m.evolve(m.time + hint, ARK_ONE_STEP, "ERKStepEvolve (one step)");
}

void ArkodeExplicit::advanceTo(Real t) {
  Impl& m = *impl_;
  if (!m.memory) throw Error("arkode: advanceTo() called before initialise()");
  const Real roundoff = 1e-14 * std::max(Real(1), std::abs(t));
  if (t < m.time - roundoff)
    throw InputError("end_time", "lies before the current time " + std::to_string(m.time));
  if (std::abs(t - m.time) <= roundoff) return;
  // Set for every interval: with a fixed step ERKStepEvolve would otherwise step past t and
  // interpolate back; with the stop time it shortens the last step and lands on t.
  m.check(ERKStepSetStopTime(m.memory, t), "ERKStepSetStopTime");
  const Real reached = m.evolve(t, ARK_NORMAL, "ERKStepEvolve");
  if (std::abs(reached - t) > 1e-12 * std::max(Real(1), std::abs(t)))
    throw Error("ARKODE ERKStepEvolve returned at t = " + std::to_string(reached) + " instead of " +
                std::to_string(t));
  m.time = t;  // ARKODE returned at the stop time; keep the caller's value exactly
}

void ArkodeExplicit::setFixedStep(Real h) {
  Impl& m = *impl_;
  if (m.options.adaptive) throw Error("arkode: setFixedStep() on an adaptive run");
  if (!(h > 0) || !std::isfinite(h))
    throw InputError("integrator.time_step", "must be positive and finite (got " + std::to_string(h) + ")");
  m.options.fixedStep = h;
  // In 6.4.1 this sets the step of every following step (and resets the initial-step estimate,
  // unused with a fixed step); ARKODE reads it at the start of each step.
  if (m.memory) m.check(ERKStepSetFixedStep(m.memory, h), "ERKStepSetFixedStep");
}

void ArkodeExplicit::setMaxStep(Real h) {
  Impl& m = *impl_;
  if (!m.options.adaptive) throw Error("arkode: setMaxStep() on a fixed-step run");
  if (!(h >= 0) || !std::isfinite(h))
    throw InputError("integrator.max_step", "must be non-negative and finite (got " + std::to_string(h) + ")");
  m.maxStep = h;
  if (m.memory) m.check(ERKStepSetMaxStep(m.memory, h), "ERKStepSetMaxStep");
}

Real ArkodeExplicit::time() const { return impl_->time; }
const Vector& ArkodeExplicit::state() const { return impl_->yData; }
const ArkodeOptions& ArkodeExplicit::options() const { return impl_->options; }
int ArkodeExplicit::order() const { return impl_->table->q; }
bool ArkodeExplicit::isInitialised() const { return impl_->memory != nullptr; }

Real ArkodeExplicit::lastStepSize() const {
  if (!impl_->memory) return 0;
  sunrealtype h = 0;
  impl_->check(ERKStepGetLastStep(impl_->memory, &h), "ERKStepGetLastStep");
  return h != 0 ? h : impl_->resumedLastStep;
}

ArkodeStatistics ArkodeExplicit::statistics() const {
  ArkodeStatistics s;
  if (!impl_->memory) return s;
  Impl& m = *impl_;
  long int value = 0;
  m.check(ERKStepGetNumSteps(m.memory, &value), "ERKStepGetNumSteps");
  s.steps = value;
  m.check(ERKStepGetNumStepAttempts(m.memory, &value), "ERKStepGetNumStepAttempts");
  s.stepAttempts = value;
  m.check(ERKStepGetNumRhsEvals(m.memory, &value), "ERKStepGetNumRhsEvals");
  s.rhsEvaluations = value;
  m.check(ERKStepGetNumErrTestFails(m.memory, &value), "ERKStepGetNumErrTestFails");
  s.failedSteps = value;
  if (m.repeatedSetupEvaluation && s.rhsEvaluations > 0) --s.rhsEvaluations;
  s.steps += m.before.steps;
  s.stepAttempts += m.before.stepAttempts;
  s.rhsEvaluations += m.before.rhsEvaluations;
  s.failedSteps += m.before.failedSteps;
  return s;
}

void ArkodeExplicit::saveState(StateArchive& archive) const {
  const Impl& m = *impl_;
  if (!m.memory) throw Error("arkode: saveState() called before initialise()");
  if (m.options.adaptive)
    throw InputError("integrator.adaptive",
                     "an adaptive ARKODE run cannot be checkpointed: its step-size controller keeps a history "
                     "ARKODE does not expose, so a restart would not be the same run; use a fixed step");
  archive.putScalar("time", m.time);
  archive.put("y", m.yData);
  archive.putScalar("fixed_step", m.options.fixedStep);
  archive.putScalar("last_step", lastStepSize());
  const ArkodeStatistics s = statistics();
  archive.put("statistics", std::vector<Real>{static_cast<Real>(s.steps), static_cast<Real>(s.stepAttempts),
                                              static_cast<Real>(s.rhsEvaluations), static_cast<Real>(s.failedSteps)});
  StateArchive system = archive.section("system");
  m.system->saveState(system);
}

void ArkodeExplicit::restoreState(const StateArchive& archive) {
  Impl& m = *impl_;
  if (!m.memory) throw Error("arkode: restoreState() called before initialise()");
  Vector y(m.yData.size());
  archive.get("y", y);
  const std::vector<Real>& counts = archive.numbers("statistics", 4);
  m.options.fixedStep = archive.scalar("fixed_step");
  initialise(*m.system, archive.scalar("time"), y);
  // Before its first step ARKODE evaluates F(t, y) once more than the stages need (it did so at the
  // original start too, and the saved count holds that one): not counted twice, so that the
  // counters read as those of one uninterrupted run (ArkodeExplicit.RestoredRunCountsAsOneRun).
  m.before = {static_cast<long>(counts[0]), static_cast<long>(counts[1]), static_cast<long>(counts[2]),
              static_cast<long>(counts[3])};
  m.repeatedSetupEvaluation = true;
  m.resumedLastStep = archive.scalar("last_step");
  m.system->restoreState(archive.section("system"));
}

}  // namespace mfwave
