#pragma once
// `mfwave plan`: what a scene will cost and how accurate it will be, predicted before any stepping
// and in seconds, from the catalogue alone.
//
//   particles     the lattice's nodes (with the ghost layers of the variants that use them)
//   memory        the method's measured base + bytes per particle (+ a sparse LU's fill), MethodCost
//   stable step   2 / omega_max of the method's interior row over the Brillouin zone (RowSpectrum),
//                 the spectral elements' closed-form Courant number, the UL-SPH's own CFL criterion
//   steps, dt     from the scene's [integrator] through the step's one home (integrators/TimeStep)
//   wall time     set-up per particle x particles + particle-steps / the measured rate
//   phase error   at the sources' dominant frequency (SourceFrequency), points per wavelength of the
//                 slowest wave, through the row's own dispersion relation and the integrator's
//
// What it cannot know is said in `notes`: boundary rows can lower the stable step below the
// interior row's (the study's power iteration then chooses a smaller dt), and a method's accuracy at
// a free surface or a load is not its plane-wave phase error.

#include "catalogue/MethodEntry.hpp"
#include "catalogue/SourceFrequency.hpp"
#include "io/scene/Scene.hpp"

#include <string>
#include <vector>

namespace mfwave {

// The method options the plan needs, read from the scene (or the catalogue's defaults).
struct MethodChoice {
  const MethodEntry* method = nullptr;
  std::string variant;                  // very_weak_sph
  std::string kernel = "cubic_spline";  // SPH kernels
  Real smoothingLengthRatio = 1;        // SPH h / dx
  int order = 2;                        // RK basis order, or the spectral elements' N
  Real supportRatio = 2.5;              // RK a / h
  Real shapeRatio = 3;                  // RB a_r / h
  bool gradientCorrection = false;      // UL-SPH kernel-gradient correction
  Real courant = 0.3;                   // UL-SPH Courant number
  Real viscosityAlpha = 0.1;            // UL-SPH Monaghan alpha (its step shrinks by 1 + 1.2 alpha)
  // A scene's own solid: the fraction of the box's lattice nodes inside it (0: the box itself). The
  // plan counts that share of the nodes, at the method's cost on solids where measured.
  Real solidFraction = 0;

  std::string label() const;  // "very_weak_sph (galerkin)", "reproducing_kernel (m = 2, a/h = 2.2)"
};

// Reads the choice of method.name's entry (method.variant, kernel, ...) with the reader of
// catalogueSchema(entry).
MethodChoice readMethodChoice(SceneReader& reader, const MethodEntry& method, int dimension);

struct Prediction {
  std::string method;          // MethodChoice::label()
  Real spacing = 0;
  Index particles = 0;
  double memoryBytes = 0;
  Real stableStep = 0;         // the step integrator.cfl multiplies
  Real timeStep = 0;
  long steps = 0;
  double setupSeconds = 0;
  double wallSeconds = 0;      // set-up + loop
  bool hasSource = false;
  Real frequency = 0;          // Hz, the sources' dominant frequency
  std::string frequencySource;
  Real pointsPerWavelength = 0;
  Real phaseError = 0;         // relative phase-speed error at `frequency` (NaN without a source)
  Real spatialPhaseError = 0;
  std::string phaseWave;       // which wave gives it
  bool growing = false;        // the interior row has growing modes
  std::vector<std::string> notes;
};

// The prediction for `scene` (its geometry, material, [integrator], sources) by `choice` at
// `spacing` (the scene's when 0).
Prediction predictScene(const Scene& scene, const MethodChoice& choice, Real spacing = 0);
// The same with the sources' dominant frequency already found (sceneSourceFrequency), for a caller
// that predicts one scene many times.
Prediction predictScene(const Scene& scene, const MethodChoice& choice, Real spacing, const SourceFrequency& source);

struct TargetAnswer {
  bool found = false;
  Prediction best;                  // the cheapest predicted run within the target
  std::vector<Prediction> candidates;  // every method and spacing tried, cheapest first
};

// The cheapest method and spacing the catalogue predicts for a phase error <= target, over every
// method that supports the scene (the published very weak SPH excluded: it does not converge) and
// the spacings scene spacing x 2^j (j = -2 .. 5) that divide the box, within `memoryLimitBytes`.
TargetAnswer cheapestForTarget(const Scene& scene, Real target, double memoryLimitBytes);

}  // namespace mfwave
