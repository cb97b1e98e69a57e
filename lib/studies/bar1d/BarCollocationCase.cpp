#include "BarCollocationCase.hpp"

#include "spectra/CollocationStability.hpp"
#include "analytic/FixedFreeBarImpact.hpp"
#include "core/AtomicFile.hpp"
#include "core/Error.hpp"
#include "core/Stopwatch.hpp"
#include "integrators/ConstrainedIntegrators.hpp"
#include "io/scene/StepLimitCheck.hpp"
#include "methods/collocation/CollocationSystem.hpp"
#include "methods/collocation/ConstrainedCollocationSystem.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/TimeLoop.hpp"
#include "observers/TimeSeries.hpp"

#include <algorithm>
#include <iomanip>
#include <memory>

namespace mfwave::bar1d {
namespace {

// Relative L2 errors of u and v at time t (trapezoidal sums on uniform points).
struct Errors {
  Real u, v, uNorm, vNorm;
};

class ErrorSampler : public Observer {
 public:
  ErrorSampler(const ConstrainedCollocationSystem& system, const ShapeFunctions<1>& shapes,
               const FixedFreeBarImpact& exact, std::vector<Vec1> points, long every)
      : system_(system), shapes_(shapes), exact_(exact), points_(std::move(points)), every_(every),
        series_("t [s]", {"relative_l2_u", "relative_l2_v", "l2_u_error [m]", "l2_u [m]"}) {}

  Errors errors(const StateView& s) const {
    const Vector u = evaluateCollocationField<1>(shapes_, system_.coefficients(s.displacement, s.time), points_);
    const Vector v = evaluateCollocationField<1>(shapes_, system_.coefficientRates(s.velocity, s.time), points_);
    Errors e{0, 0, 0, 0};
    for (std::size_t i = 0; i < points_.size(); ++i) {
      const Real x = points_[i][0], w = (i == 0 || i + 1 == points_.size()) ? 0.5 : 1.0;
      const Real ue = exact_.displacement(x, s.time), ve = exact_.velocity(x, s.time);
      e.u += w * std::pow(u[static_cast<Index>(i)] - ue, 2);
      e.v += w * std::pow(v[static_cast<Index>(i)] - ve, 2);
      e.uNorm += w * ue * ue;
      e.vNorm += w * ve * ve;
    }
    return e;
  }
  void observe(const StateView& s) override {
    (void)every_;
    const Errors e = errors(s);
    maxU_ = std::max(maxU_, e.uNorm);
    maxErrU_ = std::max(maxErrU_, e.u);
    series_.append(s.time, {std::sqrt(e.u / std::max(e.uNorm, 1e-300)), std::sqrt(e.v / std::max(e.vNorm, 1e-300)),
                            std::sqrt(e.u), std::sqrt(e.uNorm)});
  }
  void end(const StateView& s) override { observe(s); }
  // max over sampled times of ||e_u|| / max over sampled times of ||u||.
  Real maxRelativeU() const { return std::sqrt(maxErrU_ / std::max(maxU_, 1e-300)); }
  const TimeSeries& series() const { return series_; }
  void saveState(StateArchive& archive) const override {
    series_.saveState(archive);
    archive.put("maxima", std::vector<Real>{maxU_, maxErrU_});
  }
  void restoreState(const StateArchive& archive) override {
    series_.restoreState(archive);
    const std::vector<Real>& maxima = archive.numbers("maxima", 2);
    maxU_ = maxima[0];
    maxErrU_ = maxima[1];
  }

 private:
  const ConstrainedCollocationSystem& system_;
  const ShapeFunctions<1>& shapes_;
  const FixedFreeBarImpact& exact_;
  std::vector<Vec1> points_;
  long every_;
  Real maxU_ = 0, maxErrU_ = 0;
  TimeSeries series_;
};

}  // namespace

CaseResult runCase(const Study& study, int nodeCount, const std::string& folder, bool writeSeries) {
  const Stopwatch setup;
  const Scene& scene = study.scene;
  const Real x0 = scene.geometry.lower[0], length = scene.geometry.upper[0] - x0;
  const Real h = length / (nodeCount - 1);
  const Material material = Material::fromYoung(scene.material.material().youngsModulus(), 0,
                                                scene.material.density);
  const FixedFreeBarImpact exact(length, material.barSpeed(), study.v0);

  Coordinates<1> nodes;
  for (int i = 0; i < nodeCount; ++i) nodes[0].push_back(x0 + length * i / (nodeCount - 1));
  const auto shapes = makeCollocationShapes<1>(study.method, nodes, h);
  ConstrainedCollocationSystem system(assembleCollocation<1>(*shapes, fixedFreeBarPoints(nodes), material));

  // Before stepping, the whole operator's spectrum (dense: a 1-D bar has few nodes). Complex or
  // negative eigenvalues are modes that grow at any step: refused (exit 3) naming the growth rate,
  // unless stability.allow_growth. The exact central-difference step is 2 / sqrt(max |eig K|), and
  // every integrator's step is checked against its own limit (io/scene/StepLimitCheck).
  const EigenvalueStability spectrum = eigenvalueStability(system.denseStiffness());
  const std::string where = "at " + std::to_string(nodeCount) + " nodes";
  std::string note;
  if (spectrum.unconditionallyUnstable)
    note = refuseGrowingModes(scene.stability,
                              "the collocation operator " + where + " has growing modes: " + spectrum.verdict() +
                                  " (" + study.method.describe() + ")",
                              "see the stability atlas, docs/studies/stability-atlas.md");
  const Real lambdaMax = spectrum.largestModulus;
  const Real criticalDt = 2 / std::sqrt(lambdaMax);
  const Real dt = scene.integrator.timeStepFor(criticalDt);
  const StepLimitCheck check = checkStepLimit(scene.integrator, scene.stability, std::sqrt(lambdaMax), dt, criticalDt,
                                              "the exact spectrum of the collocation operator", where);
  if (!check.note.empty()) note += (note.empty() ? "" : "; ") + check.note;

  // Initial state at interior points: u = 0, v = v0 (the boundary rows enforce u(0) = 0).
  const Vector U0 = Vector::Zero(system.size());
  const Vector V0 = Vector::Constant(system.size(), study.v0);
  const std::unique_ptr<SecondOrderIntegrator> integrator =
      makeConstrainedIntegrator(scene.integrator.name, scene.integrator.options);
  integrator->initialise(system, 0, U0, V0, dt);

  std::vector<Vec1> errorPoints;
  for (int i = 0; i < study.errorPoints; ++i) errorPoints.emplace_back(x0 + length * i / (study.errorPoints - 1));
  const long steps = scene.integrator.stepsFor(criticalDt);
  const long every = std::max<long>(1, steps / study.errorSamples);
  ErrorSampler sampler(system, *shapes, exact, errorPoints, every);
  StabilityMonitor monitor(scene.stability.options(1, 0));
  TimeLoop loop;
  loop.add(monitor);
  loop.add(sampler, every);
  const double setupSeconds = setup.seconds();
  const RunStatistics stats = loop.run(*integrator, scene.integrator.endTime);

  const Errors e = sampler.errors(integrator->state());
  CaseResult result;
  result.nodes = nodeCount;
  result.h = h;
  result.errorU = std::sqrt(e.u / e.uNorm);
  result.errorV = std::sqrt(e.v / e.vNorm);
  result.maxErrorU = sampler.maxRelativeU();
  if (!note.empty()) result.notes.push_back(note);
  noteAllowedGrowth(result.notes, "", {monitor.growthMessage()});
  CaseRecord& record = result.record;
  record.name = std::to_string(nodeCount) + " nodes";
  record.particles = nodeCount;
  result.recordLoop(stats);
  record.timeStep = dt;
  record.stableTimeStep = criticalDt;
  record.simulatedTime = scene.integrator.endTime;
  record.setupSeconds = setupSeconds;
  record.errors = {{"relative_l2_u", result.errorU},
                   {"relative_l2_v", result.errorV},
                   {"max_relative_l2_u_over_time", result.maxErrorU}};
  record.primaryError = "relative_l2_u";
  if (writeSeries) {
    const std::string name = "nodes-" + std::to_string(nodeCount);
    const std::string stem = folder + "/" + name;
    sampler.series().writeCsv(stem + "-errors.csv");
    const StateView s = integrator->state();
    const Vector u = evaluateCollocationField<1>(*shapes, system.coefficients(s.displacement, s.time), errorPoints);
    const Vector v = evaluateCollocationField<1>(*shapes, system.coefficientRates(s.velocity, s.time), errorPoints);
    AtomicFile profile(stem + "-profile.csv");
    profile.stream() << "x [m],u [m],u_exact [m],v [m/s],v_exact [m/s]\n" << std::setprecision(10);
    for (std::size_t i = 0; i < errorPoints.size(); ++i) {
      const Real x = errorPoints[i][0];
      profile.stream() << x << ',' << u[static_cast<Index>(i)] << ',' << exact.displacement(x, s.time) << ','
                       << v[static_cast<Index>(i)] << ',' << exact.velocity(x, s.time) << '\n';
    }
    profile.commit();
    result.files = {name + "-errors.csv", name + "-profile.csv"};
  }
  return result;
}

}  // namespace mfwave::bar1d
