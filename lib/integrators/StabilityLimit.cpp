#include "integrators/StabilityLimit.hpp"

#include "core/Error.hpp"

#include <cmath>
#include <complex>
#include <limits>

namespace mfwave {

Real rungeKuttaAmplification(const ButcherCoefficients& table, Real y) {
  // Stage values of y' = z y from y = 1: Y_i = 1 + z sum_{j<i} a_ij Y_j; R = 1 + z sum_i b_i Y_i.
  const auto s = static_cast<std::size_t>(table.stages);
  const std::complex<Real> z(0, y);
  std::vector<std::complex<Real>> stage(s);
  std::complex<Real> r = 1;
  for (std::size_t i = 0; i < s; ++i) {
    std::complex<Real> sum = 0;
    for (std::size_t j = 0; j < i; ++j) sum += table.a[i * s + j] * stage[j];
    stage[i] = 1.0 + z * sum;
    r += z * table.b[i] * stage[i];
  }
  return std::abs(r);
}

Real rungeKuttaImaginaryLimit(const ButcherCoefficients& table, Real tolerance, Real yMax) {
  const auto grows = [&](Real y) { return rungeKuttaAmplification(table, y) > 1 + tolerance; };
  const int samples = 100000;
  Real previous = 0;
  for (int k = 1; k <= samples; ++k) {
    const Real y = yMax * k / samples;
    if (grows(y)) {
      if (k == 1) return 0;
      Real lo = previous, hi = y;  // |R| <= 1 + tol at lo, above at hi
      for (int it = 0; it < 60; ++it) {
        const Real mid = 0.5 * (lo + hi);
        (grows(mid) ? hi : lo) = mid;
      }
      return lo;
    }
    previous = y;
  }
  return yMax;
}

IntegratorLimit integratorLimit(const std::string& integrator, Real beta, Real gamma) {
  if (integrator.rfind("newmark:", 0) == 0) {
    const NamedIntegrator spec = namedIntegrator(integrator);
    IntegratorLimit out = integratorLimit("newmark", spec.options.newmarkBeta, spec.options.newmarkGamma);
    out.integrator = integrator;
    return out;
  }
  IntegratorLimit out;
  out.integrator = integrator;
  const Real infinity = std::numeric_limits<Real>::infinity();
  if (integrator == "central_difference" || integrator == "leapfrog") {
    out.omegaDtLimit = 2;
    out.note = "omega_max dt <= 2 (the step limit 2 / omega_max)";
    return out;
  }
  if (integrator == "newmark") {
    if (!(gamma >= 0.5)) {
      out.omegaDtLimit = 0;
      out.note = "gamma < 1/2 amplifies every mode";
    } else if (2 * beta >= gamma) {
      out.omegaDtLimit = infinity;
      out.note = "unconditionally stable (2 beta >= gamma >= 1/2)";
    } else {
      out.omegaDtLimit = 1 / std::sqrt(gamma / 2 - beta);
      out.note = "conditionally stable: omega_max dt <= 1 / sqrt(gamma / 2 - beta)";
    }
    return out;
  }
  const std::string prefix = "arkode:";
  if (integrator.rfind(prefix, 0) == 0) {
    const ButcherCoefficients table = ArkodeExplicit::coefficients(integrator.substr(prefix.size()));
    out.omegaDtLimit = rungeKuttaImaginaryLimit(table);
    if (out.omegaDtLimit < 0.5) {
      out.growthPerStepAtOne = rungeKuttaAmplification(table, 1) - 1;
      out.note = "|R(i y)| > 1 from y = " + std::to_string(out.omegaDtLimit) +
                 ": undamped modes grow at practically any step";
    } else {
      out.note = "order " + std::to_string(table.order) + ", " + std::to_string(table.stages) +
                 " stages: the stability region's extent along the imaginary axis";
    }
    return out;
  }
  throw InputError("integrator", "unknown integrator '" + integrator +
                                     "'; valid: central_difference, leapfrog, newmark, newmark:<beta>, arkode:<table>");
}

IntegratorLimit integratorLimit(const std::string& name, const IntegratorOptions& options) {
  if (name == "newmark") return integratorLimit(name, options.newmarkBeta, options.newmarkGamma);
  if (name == "arkode") {
    if (options.arkode.adaptive) {
      IntegratorLimit limit;
      limit.integrator = "arkode:" + options.arkode.table + " (adaptive)";
      limit.omegaDtLimit = std::numeric_limits<Real>::infinity();
      limit.note = "adaptive: the error control chooses the step";
      return limit;
    }
    return integratorLimit("arkode:" + options.arkode.table);
  }
  return integratorLimit(name);
}

namespace {

// The larger |root| of a Newmark step's characteristic equation on u'' = -omega^2 u (Hughes,
// The Finite Element Method, 9.1): amplification matrix eigenvalues of the (u, v, a) recurrence,
// here from the two-step form lambda^2 - 2 A1 lambda + A2 = 0 with
//   A1 = 1 - (gamma + 1/2) w^2 / (2 D),  A2 = 1 - (gamma - 1/2) w^2 / D,  D = 1 + beta w^2,  w = omega dt.
Real newmarkGrowth(Real beta, Real gamma, Real w) {
  const Real w2 = w * w, d = 1 + beta * w2;
  const Real a1 = 1 - (gamma + 0.5) * w2 / (2 * d), a2 = 1 - (gamma - 0.5) * w2 / d;
  const std::complex<Real> root = std::sqrt(std::complex<Real>(a1 * a1 - a2, 0));
  return std::max(std::abs(a1 + root), std::abs(a1 - root));
}

}  // namespace

StepVerdict judgeStep(const std::string& name, const IntegratorOptions& options, Real omegaMax, Real dt) {
  if (!(omegaMax > 0) || !std::isfinite(omegaMax))
    throw InputError("omega_max", "the operator's largest frequency must be positive and finite");
  StepVerdict v;
  v.limit = integratorLimit(name, options);
  v.omegaMax = omegaMax;
  v.dt = dt;
  v.limitDt = v.limit.omegaDtLimit / omegaMax;
  v.aboveLimit = dt > v.limitDt * (1 + 1e-12);
  const Real w = omegaMax * dt;
  if (name == "arkode" && !options.arkode.adaptive) {
    v.growthPerStep = std::max<Real>(1, rungeKuttaAmplification(ArkodeExplicit::coefficients(options.arkode.table), w));
    v.integratorUnstable = v.limit.omegaDtLimit < 0.5;
  } else if (name == "newmark") {
    v.growthPerStep = std::max<Real>(1, newmarkGrowth(options.newmarkBeta, options.newmarkGamma, w));
    v.integratorUnstable = options.newmarkGamma < 0.5;
  } else if (name == "central_difference" || name == "leapfrog") {
    v.growthPerStep = std::max<Real>(1, newmarkGrowth(0, 0.5, w));
  }
  return v;
}

std::vector<IntegratorLimit> integratorLimits() {
  std::vector<IntegratorLimit> all = {integratorLimit("central_difference"), integratorLimit("leapfrog"),
                                      integratorLimit("newmark"), integratorLimit("newmark:linear_acceleration"),
                                      integratorLimit("newmark:fox_goodwin")};
  for (const std::string& table : ArkodeExplicit::tableNames()) all.push_back(integratorLimit("arkode:" + table));
  return all;
}

}  // namespace mfwave
