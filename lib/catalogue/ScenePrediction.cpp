#include "catalogue/ScenePrediction.hpp"

#include "spectra/LatticeMethods.hpp"
#include "spectra/SpectralElementDispersion.hpp"
#include "catalogue/LatticeRows.hpp"
#include "catalogue/MethodCatalogue.hpp"
#include "catalogue/RowSpectrum.hpp"
#include "catalogue/SceneSupport.hpp"
#include "catalogue/SourceFrequency.hpp"
#include "core/Error.hpp"
#include "particles/BoxFace.hpp"
#include "integrators/TimeStep.hpp"
#include "io/scene/Format.hpp"

#include <algorithm>
#include <functional>
#include <cmath>
#include <limits>
#include <sstream>

namespace mfwave {
namespace {

// The spectral elements' stable step as a Courant number c_p dt / dx at the mean node spacing dx,
// for the central difference limit 2 / omega_max from the Gershgorin bound the runs use (GLL nodes
// crowd at element edges, so it falls with N). Measured on lamb2d.toml and lamb3d.toml (rho = lambda
// = mu = 1) at dx near 0.25 and 0.5 for N = 1 .. 8 (2026-11-28); the bound scales as c_p / dx.
Real spectralElementCourant(int order, int dimension) {
  static const Real planeStrain[] = {0, 0.8662, 0.7005, 0.5731, 0.4712, 0.3972, 0.3426, 0.3009, 0.2681};
  static const Real solid[] = {0, 0.7747, 0.6130, 0.4886, 0.3990, 0.3356, 0.2891, 0.2537, 0.2260};
  const int n = std::clamp(order, 1, 8);
  return dimension == 3 ? solid[n] : planeStrain[n];
}

// The spectral elements are N spacings wide: each side must hold whole elements.
void checkSpectralElementLattice(const GeometrySpec& g, int order) {
  const Real width = order * g.spacing;
  for (int a = 0; a < g.dimension; ++a) {
    const Real elements = (g.upper[static_cast<std::size_t>(a)] - g.lower[static_cast<std::size_t>(a)]) / width;
    if (std::abs(elements - std::round(elements)) > 1e-9 * elements)
      throw InputError("geometry.spacing", "spectral elements of order " + std::to_string(order) + " at spacing " +
                                               scene::formatNumber(g.spacing) + " are " + scene::formatNumber(width) +
                                               " wide, which does not divide the box " + g.describeBox());
  }
}

// The interior row of the choice in the lattice tools (LatticeRows.hpp).
std::string latticeRowName(const MethodChoice& c) {
  return latticeRowOf(c.method->name, c.variant, c.gradientCorrection);
}

LatticeMethodSettings latticeSettings(const MethodChoice& c, const Material& material) {
  LatticeMethodSettings s;
  s.material = material;
  s.kernel = c.kernel;
  s.smoothingLengthRatio = c.smoothingLengthRatio;
  s.rkOrder = c.order;
  s.rkSupportRatio = c.supportRatio;
  s.rbShapeRatio = c.shapeRatio;
  return s;
}

Index ghostParticles(const GeometrySpec& g) {
  if (g.ghostLayers <= 0 || g.ghostFaces == 0) return 0;
  Index grown = 1;
  for (int a = 0; a < g.dimension; ++a) {
    Index n = g.intervals[static_cast<std::size_t>(a)] + 1;
    if (g.ghostFaces & faceBit(2 * a)) n += g.ghostLayers;
    if (g.ghostFaces & faceBit(2 * a + 1)) n += g.ghostLayers;
    grown *= n;
  }
  return grown - g.particleCount();
}

struct RowFigures {
  bool growing = false;
  TimeStepChoice step;
  RowPhaseError phase;  // of the sources' waves at step.dt (none without a frequency)
};

// The method's interior row at spacing dx: whether it grows, the step `stepOf` takes from its
// omega_max, and the phase error of waves of `frequency` (Hz; 0: none) stepped at that step by `kind`.
template <int D>
RowFigures latticeRowFigures(const MethodChoice& c, const Material& material, Real dx, Real frequency,
                             const std::function<TimeStepChoice(Real omegaMax)>& stepOf, IntegratorKind kind) {
  const MethodLatticeStencil<D> row =
      latticeMethodStencil<D>(latticeRowName(c), latticeSettings(c, material), dx, "method.name");
  const RowSpectrum spectrum = rowSpectrum<D>(row, dx);
  RowFigures f;
  f.growing = spectrum.growing;
  f.step = stepOf(spectrum.omegaMax);
  if (frequency > 0) f.phase = rowPhaseError<D>(row, material, dx, frequency, f.step.dt, kind);
  return f;
}

RowFigures latticeRowFigures(int dimension, const MethodChoice& c, const Material& material, Real dx, Real frequency,
                             const std::function<TimeStepChoice(Real omegaMax)>& stepOf, IntegratorKind kind) {
  if (dimension == 1) return latticeRowFigures<1>(c, material, dx, frequency, stepOf, kind);
  if (dimension == 2) return latticeRowFigures<2>(c, material, dx, frequency, stepOf, kind);
  return latticeRowFigures<3>(c, material, dx, frequency, stepOf, kind);
}

MethodChoice defaultChoice(const MethodEntry& m, int dimension) {
  MethodChoice c;
  c.method = &m;
  if (!m.variants.empty()) c.variant = m.variants.front();
  if (m.name == "very_weak_sph") c.smoothingLengthRatio = 1.0;
  if (m.name == "updated_lagrangian_sph" || m.name == "total_lagrangian_sph") c.smoothingLengthRatio = 1.3;
  if (m.name == "spectral_element") c.order = 4;
  if (m.name == "reproducing_kernel") c.supportRatio = dimension == 3 ? 2.2 : 2.5;
  if (m.name == "total_lagrangian_sph") c.gradientCorrection = true;
  return c;
}

}  // namespace

std::string MethodChoice::label() const {
  std::ostringstream s;
  s << method->name;
  if (!variant.empty()) s << " (" << variant << ")";
  else if (method->name == "reproducing_kernel") s << " (m = " << order << ", a/h = " << supportRatio << ")";
  else if (method->name == "spectral_element") s << " (N = " << order << ")";
  else if (method->name == "updated_lagrangian_sph" && gradientCorrection) s << " (corrected gradients)";
  return s.str();
}

MethodChoice readMethodChoice(SceneReader& reader, const MethodEntry& m, int dimension) {
  MethodChoice c = defaultChoice(m, dimension);
  if (m.name == "very_weak_sph") {
    c.variant = reader.string("method.variant");
    c.kernel = reader.string("method.kernel");
    c.smoothingLengthRatio = reader.number("method.smoothing_length_ratio");
  } else if (m.name == "updated_lagrangian_sph") {
    c.kernel = reader.string("method.kernel");
    c.smoothingLengthRatio = reader.number("method.smoothing_length_ratio");
    c.gradientCorrection = reader.boolean("method.kernel_gradient_correction");
    c.courant = reader.number("method.courant");
    c.viscosityAlpha = reader.number("method.viscosity_alpha");
  } else if (m.name == "reproducing_kernel") {
    c.order = static_cast<int>(reader.integer("method.order"));
    if (reader.has("method.support_ratio"))  // its default is the study's: the catalogue's by dimension
      c.supportRatio = reader.number("method.support_ratio");
  } else if (m.name == "radial_basis") {
    c.shapeRatio = reader.number("method.shape_ratio");
  } else if (m.name == "spectral_element") {
    c.order = static_cast<int>(reader.integer("method.order"));
  }
  return c;
}

Prediction predictScene(const Scene& scene, const MethodChoice& choice, Real spacing) {
  return predictScene(scene, choice, spacing, sceneSourceFrequency(scene));
}

Prediction predictScene(const Scene& scene, const MethodChoice& c, Real spacing, const SourceFrequency& source) {
  const MethodEntry& m = *c.method;
  const GeometrySpec g = spacing > 0 && std::abs(spacing - scene.geometry.spacing) > 1e-12 * spacing
                             ? scene.geometry.withLattice(scene.geometry.lower, scene.geometry.upper, spacing)
                             : scene.geometry;
  const int d = g.dimension;
  const Material material = scene.material.material();
  Prediction p;
  p.method = c.label();
  p.spacing = g.spacing;
  p.particles = g.particleCount();
  const bool ghosts = m.name == "very_weak_sph" && c.variant != "galerkin";
  if (ghosts) p.particles += ghostParticles(g);
  const std::size_t dim = static_cast<std::size_t>(d - 1);
  MethodCost cost = m.cost;
  if (c.solidFraction > 0) {
    p.particles = static_cast<Index>(std::llround(c.solidFraction * static_cast<Real>(g.particleCount())));
    if (cost.solidBytesPerParticle[dim] > 0) {
      cost.baseMiB[dim] = cost.solidBaseMiB[dim];
      cost.bytesPerParticle[dim] = cost.solidBytesPerParticle[dim];
      cost.particleStepsPerSecond[dim] = cost.solidParticleStepsPerSecond[dim];
      cost.setupSecondsPerParticle[dim] = cost.solidSetupSecondsPerParticle[dim];
      cost.fillMiB[dim] = 0;
      cost.growthExponent = 1;
      p.notes.push_back("the solid's share of the box's lattice (" + std::to_string(std::lround(100 * c.solidFraction)) +
                        " %) at the cost measured on solids (" + cost.solidMeasured + ")");
    } else {
      p.notes.push_back("the solid's share of the box's lattice (" + std::to_string(std::lround(100 * c.solidFraction)) +
                        " %), at the method's cost on boxes (none measured on solids)");
    }
  }

  p.hasSource = source.found;
  p.frequency = source.frequency;
  p.frequencySource = source.found ? source.source + " (" + source.rule + ")" : "";

  const std::size_t di = dim;
  const double n = static_cast<double>(p.particles);
  p.memoryBytes = (cost.baseMiB[di] + cost.fillMiB[di] * std::pow(n / cost.fillNodes, cost.fillExponent)) * 1048576.0 +
                  cost.bytesPerParticle[di] * n;
  if (cost.particleStepsPerSecond[di] <= 0)
    p.notes.push_back(m.name + " has no measured rate in " + std::to_string(d) + "-D: the wall time is unknown");

  TimeStepChoice step;
  if (m.interiorRow == InteriorRow::SpectralElement) {
    checkSpectralElementLattice(g, c.order);
    p.stableStep = spectralElementCourant(c.order, d) * g.spacing / material.pWaveSpeed();
    step = chooseTimeStep(scene.integrator.stepRule(), p.stableStep);
    if (p.hasSource) {
      // The elements' own dispersion along a lattice axis (Bloch analysis of one element: exact for
      // P and S waves along an axis of the tensor elements), then the integrator's.
      const Real omega = 2 * kPi * p.frequency;
      p.phaseError = -1;
      for (const bool shear : {false, true}) {
        const Real speed = shear ? material.sWaveSpeed() : material.pWaveSpeed();
        const Real omegaH = spectralElementFrequency(c.order, g.spacing, speed, omega / speed);
        Real total = std::abs(discreteFrequency(omegaH, step.dt, scene.integrator.kind) / omega - 1);
        if (std::isnan(total)) total = std::numeric_limits<Real>::infinity();
        if (total > p.phaseError) {
          p.phaseError = total;
          p.spatialPhaseError = std::abs(omegaH / omega - 1);
          p.pointsPerWavelength = speed / p.frequency / g.spacing;
          p.phaseWave = std::string(shear ? "S" : "P") + " along an axis";
        }
      }
    }
  } else if (m.name == "updated_lagrangian_sph") {
    // The method's own step criteria at rest: courant h / (c_p (1 + 1.2 alpha)) (UpdatedLagrangianSph::
    // stableStep: the signal speed c_p with the artificial viscosity's share; no force limit at rest),
    // which integrator.cfl multiplies.
    p.stableStep = c.courant * c.smoothingLengthRatio * g.spacing / (material.pWaveSpeed() * (1 + 1.2 * c.viscosityAlpha));
    step = chooseTimeStep(scene.integrator.stepRule(), p.stableStep);
    if (p.hasSource) {
      // The row linearised about rest, stepped at the method's own step by leapfrog.
      const RowFigures f = latticeRowFigures(d, c, material, g.spacing, p.frequency,
                                             [&step](Real) { return step; }, IntegratorKind::Leapfrog);
      p.growing = f.growing;
      p.phaseError = f.phase.total;
      p.spatialPhaseError = f.phase.spatial;
      p.pointsPerWavelength = f.phase.pointsPerWavelength;
      p.phaseWave = f.phase.wave + " (the row linearised about rest)";
    }
  } else {
    const TimeStepRule rule = scene.integrator.stepRule();
    const RowFigures f = latticeRowFigures(
        d, c, material, g.spacing, p.hasSource ? p.frequency : 0,
        [&rule](Real omegaMax) { return chooseTimeStep(rule, centralDifferenceStableStep(omegaMax)); },
        scene.integrator.kind);
    step = f.step;
    p.stableStep = f.step.stableStep;
    p.growing = f.growing;
    if (p.hasSource) {
      p.phaseError = f.phase.total;
      p.spatialPhaseError = f.phase.spatial;
      p.pointsPerWavelength = f.phase.pointsPerWavelength;
      p.phaseWave = f.phase.wave;
    }
    p.notes.push_back("stable step from the interior row; boundary rows may lower it (the run's power iteration "
                      "decides)");
  }
  if (p.hasSource)
    p.notes.push_back("the phase error is that of bulk plane waves at the dominant frequency: a free surface, a "
                      "load's kinks and boundary rows add errors it does not predict (docs/studies/which-method.md)");
  if (!p.hasSource) {
    p.phaseError = std::numeric_limits<Real>::quiet_NaN();
    p.notes.push_back("no time-dependent source: no dominant frequency, no phase error predicted");
  }
  if (p.growing) p.notes.push_back("the interior row has growing modes (omega^2 < 0): the run will be refused or grow");
  p.timeStep = step.dt;
  p.steps = step.steps;
  const double growth = std::pow(n / cost.growthNodes[di], cost.growthExponent - 1);
  const double rate = cost.particleStepsPerSecond[di] / growth;
  p.setupSeconds = cost.setupSecondsPerParticle[di] * n * growth;
  p.wallSeconds = rate > 0 ? p.setupSeconds + n * static_cast<double>(p.steps) / rate
                           : std::numeric_limits<double>::quiet_NaN();
  return p;
}

TargetAnswer cheapestForTarget(const Scene& scene, Real target, double memoryLimitBytes) {
  TargetAnswer answer;
  const SourceFrequency source = sceneSourceFrequency(scene);  // the same for every candidate
  for (const MethodEntry& m : methodCatalogue()) {
    if (!unsupportedFeatures(scene, m).empty()) continue;
    std::vector<MethodChoice> choices;
    if (m.variants.empty()) choices.push_back(defaultChoice(m, scene.geometry.dimension));
    for (const std::string& v : m.variants) {
      if (v == "published") continue;  // does not converge (docs/studies/lamb3d.md)
      MethodChoice c = defaultChoice(m, scene.geometry.dimension);
      c.variant = v;
      choices.push_back(c);
    }
    for (const MethodChoice& c : choices)
      for (int j = -2; j <= 5; ++j) {
        const Real dx = scene.geometry.spacing * std::pow(2.0, -j);
        Prediction p;
        try {
          p = predictScene(scene, c, dx, source);
        } catch (const InputError&) {
          continue;  // the spacing does not divide the box, or the row cannot be built there
        }
        if (p.growing || !(p.memoryBytes <= memoryLimitBytes) || !std::isfinite(p.wallSeconds)) continue;
        answer.candidates.push_back(p);
      }
  }
  std::sort(answer.candidates.begin(), answer.candidates.end(),
            [](const Prediction& a, const Prediction& b) { return a.wallSeconds < b.wallSeconds; });
  for (const Prediction& p : answer.candidates)
    if (p.phaseError <= target) {
      answer.found = true;
      answer.best = p;
      break;
    }
  return answer;
}

}  // namespace mfwave
