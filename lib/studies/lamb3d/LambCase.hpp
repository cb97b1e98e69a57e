#pragma once
// One run of the lamb3d / lamb2d study: a scene (possibly re-gridded, re-boxed or with other
// boundaries) through the very weak form SPH and central differences, or through RK collocation
// (LambCollocationCase.hpp), its probes compared with the exact response of the half-space, or
// (lamb2d) through the updated-Lagrangian SPH for solids (LambSolidCase.hpp).

#include "numerics/SignalComparison.hpp"
#include "io/run/StudyCases.hpp"
#include "io/scene/Scene.hpp"
#include "studies/lamb3d/LambSolidSpec.hpp"
#include "wiring/CollocationSpec.hpp"
#include "wiring/VeryWeakSphSpec.hpp"

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace mfwave::lamb3d {

// What distinguishes one run from the scene's own set-up.
struct CaseSettings {
  std::string name;                 // "galerkin_0.5", "published_0.25", "strong_filter", "free_block",
                                    // "rk_m2_a2.5_0.125", "ulsph_0.25", ...
  GeometrySpec geometry;            // box and spacing of this run
  bool freeFaces = false;           // every face free (the large-block comparison)
  VeryWeakSphSpec method;           // variant, corrections, smoothing (rate at this spacing), deconvolution
  // The figure case: VTK / PNG frames as the scene's [output] asks (the very weak SPH) and the exact
  // response on a fine time grid, exact.csv (either method).
  bool writeFrames = false;
  // Set: the case runs RK collocation with these shape functions instead of the very weak SPH
  // (`method` is then not used).
  std::optional<CollocationSpec> collocation;
  // Set: the case runs the updated-Lagrangian SPH for solids (`method` is then not used).
  std::optional<LambSolidSpec> solid;
  // Set: the case runs the spectral-element method of this order N (LambSpectralElementCase.hpp)
  // with elements N spacings wide (`method` is then not used).
  std::optional<int> spectralElementOrder;

  bool isCollocation() const { return collocation.has_value(); }
  bool isSolid() const { return solid.has_value(); }
  bool isSpectralElement() const { return spectralElementOrder.has_value(); }
  bool isVeryWeakSph() const { return !isCollocation() && !isSolid() && !isSpectralElement(); }
  // The method of the cases table: the very weak SPH's variant ("galerkin"), "rk m=2 a/h=2.5",
  // "ul-sph alpha=1 beta=0 kgc" or "sem N=4".
  std::string methodLabel() const;
};

struct ProbeResult {
  std::string name;
  bool hasExact = false;
  SignalErrors raw;        // the state against the exact response
  SignalErrors reported;   // what the method reports: deconvolved by eq. (35) when it is on, else the state
  // Relative L2 distance of the exact response to the load spread over the surface by the kernel
  // (its plane density) from the exact response: the part of the error that the kernel's width
  // alone explains. NaN when not computed.
  Real kernelFloor = std::numeric_limits<Real>::quiet_NaN();
};

// The record (StudyCase) holds particles, steps, dt, the stable step estimate, the set-up
// (assembly) and loop times and the peak memory (of the process when the case ended: cases run
// smallest first). An RK collocation case fills meanNeighbours (nodes per collocation point) and
// operatorNonZeros (of A) too; the other figures below are the very weak SPH's (an RK case leaves
// them at zero and the table blank).
struct CaseResult : StudyCase {
  CaseSettings settings;
  Index ghosts = 0;
  Real smoothingLength = 0;
  Real meanNeighbours = 0;
  Index operatorNonZeros = 0;
  Real operatorMiB = 0;             // K, T, C and M in CSR (values + indices)
  Real stableStepGershgorin = 0;
  // The energy ledger: kinetic + |strain| at the end over its largest value, the largest balance
  // drift over the largest energy, and the growth the run went on through (stability.allow_growth).
  Real energyFinalFraction = 0, energyBalanceDrift = 0;
  std::string energyGrowth;
  std::vector<ProbeResult> probes;
};

struct StudySettings {
  Scene scene;
  Real errorWindow = 6;           // s: the errors are over 0 <= t <= errorWindow
  Real arrivalFraction = 0.1;     // arrival: first |v| >= fraction * |exact peak|
  bool kernelFloor = false;       // compute ProbeResult::kernelFloor
};

// Runs one case and writes "<folder>/<case>-probes.csv" (time, then raw, reported and exact
// columns per probe) and, if asked, frames "<case>_NNNNNN.vtp" with "<case>.pvd". A collocation case
// runs runCollocationCase (LambCollocationCase.hpp), an updated-Lagrangian SPH case runSolidCase
// (LambSolidCase.hpp), a spectral-element case runSpectralElementCase (LambSpectralElementCase.hpp).
CaseResult runCase(const StudySettings& study, const CaseSettings& settings, const std::string& folder,
                   bool progress);

}  // namespace mfwave::lamb3d
