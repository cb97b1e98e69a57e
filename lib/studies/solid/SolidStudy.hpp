#pragma once
// The solid study (issue 48): any scene whose solid is described by shapes (wiring/SolidScene) run by
// the Galerkin very weak SPH on cut lattice cells (methods/very_weak_sph/CutCellGalerkin), or on a
// staircase of whole cells as the baseline, and by RK collocation on lattice and surface nodes
// (methods/collocation/SolidCollocationNodes), at each of study.spacings; loads anywhere (point forces,
// moment tensors, tractions on a named surface), probes anywhere recording a component along any
// direction, and the exact 2-D Lamb response where the scene is a loaded half-plane of any
// inclination (study.reference = "lamb_strip": LambStripLoad in the half-plane's own coordinates).

#include "io/scene/Scene.hpp"
#include "io/scene/SceneSchema.hpp"
#include "methods/very_weak_sph/CutCellGalerkin.hpp"
#include "observers/TimeSeries.hpp"
#include "wiring/CollocationSpec.hpp"
#include "wiring/SolidScene.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace mfwave::solid {

inline constexpr const char* kProgram = "solid";

// The scene keys the study reads besides the common ones: the solid (addSolidKeys), the method's
// cut-cell options, probe directions and the study's.
SceneSchema solidSchema();

template <int D>
struct SolidProbe {
  std::string name;
  Vec<D> position = Vec<D>::Zero();
  Vec<D> direction = Vec<D>::Zero();  // unit: the probe records the field's component along it
  bool velocity = true;
};

// The exact reference of a loaded half-plane: the load's centre, the half-plane's outward normal
// and a tangent, the strip's half-width, pressure and history breakpoints.
struct HalfPlaneLamb {
  std::vector<Real> centre, normal, tangent;
  Real halfWidth = 0, pressure = 0;
  std::vector<Real> times, values;
};

template <int D>
struct SolidPlan {
  Scene scene;
  SceneSolid<D> solid;
  std::vector<SolidProbe<D>> probes;
  std::vector<Real> spacings;  // the scene's first
  std::vector<std::string> methods;  // study.methods: the methods of the catalogue that run solids
  bool runs(const std::string& method) const {
    return std::find(methods.begin(), methods.end(), method) != methods.end();
  }
  std::vector<CutCells> cells; // very_weak_sph: cut, then staircase when compared
  CollocationSpec collocation; // reproducing_kernel: its shape functions
  std::vector<std::string> fixedSurfaces;  // [[surface_boundary]] of type fixed: '<shape>.<surface>'
  // Whether the surface point x (on the solid's surface) belongs to a fixed surface.
  bool fixedAt(const Vec<D>& x) const;
  int depth = 4;
  Real smallCellFraction = 0.25;
  Real errorWindow = 0;
  std::optional<HalfPlaneLamb> lamb;
};

// Reads and checks everything before any work: the method (by the catalogue), the box faces
// (free or transmitting), the loads (point_force, moment_tensor, surface_traction on a named
// surface of the solid; 2-D for surface tractions), the probes (inside the solid), the reference.
template <int D>
SolidPlan<D> readSolidPlan(SceneReader& reader, const Scene& scene);

struct SolidCaseResult {
  std::string name;
  std::string method;  // very_weak_sph or reproducing_kernel
  Real spacing = 0;
  std::string cells;   // cut, staircase; nodes (collocation: lattice and surface nodes); fill (UL- and TL-SPH)
  Index unknowns = 0, extended = 0, cutCells = 0;
  Real volume = 0, smallestKept = 0;
  Real stableStep = 0, dt = 0;
  long steps = 0;
  Real setupSeconds = 0, runSeconds = 0, peakMiB = 0;
  std::vector<Real> relativeL2, peakError, arrivalError;  // per probe (empty without a reference)
  std::vector<std::string> files;
};

// One case: the cut (or staircase) Galerkin lattice of `plan` at `spacing`, stepped to the end time,
// its probes written to <folder>/<name>-probes.csv (with the exact series beside them when there is a
// reference) and scored; frames when asked (the first case).
template <int D>
SolidCaseResult runSolidCase(const SolidPlan<D>& plan, Real spacing, CutCells cells, const std::string& folder,
                             bool frames, bool progress);

// One RK collocation case (reproducing_kernel) of `plan` at `spacing`: the lattice nodes well inside
// the solid, nodes on its surfaces with traction rows, the box faces fixed where they transmit
// (methods/collocation/SolidCollocationNodes); written and scored as runSolidCase's. Named
// rk_<spacing>. Throws InstabilityError (naming the node) when the run blows up.
template <int D>
SolidCaseResult runSolidCollocationCase(const SolidPlan<D>& plan, Real spacing, const std::string& folder, bool frames,
                                        bool progress);

// One updated-Lagrangian SPH case (updated_lagrangian_sph) of `plan` at `spacing`: a body-fitted fill
// of the solid at small amplitude (kSmallAmplitude), leapfrog at the method's own step, the box's faces
// free; written and scored as runSolidCase's. Named ulsph_<spacing>.
inline constexpr Real kSmallAmplitude = 1e-4;  // the traction's factor; probes record v / eps
template <int D>
SolidCaseResult runSolidSphCase(const SolidPlan<D>& plan, Real spacing, const std::string& folder, bool progress);

// One total-Lagrangian SPH case (total_lagrangian_sph) of `plan` at `spacing`: the UL-SPH case's fill,
// loads and probes, the scene's central difference; written and scored as runSolidCase's. Named
// tlsph_<spacing>.
template <int D>
SolidCaseResult runSolidTotalLagrangianCase(const SolidPlan<D>& plan, Real spacing, const std::string& folder,
                                            bool progress);

// The exact velocity (or displacement) along the inward normal of the half-plane at `x`.
std::vector<Real> lambHalfPlaneSeries(const HalfPlaneLamb& lamb, const Material& material, const std::vector<Real>& x,
                                      const std::vector<Real>& times, bool velocity);

}  // namespace mfwave::solid
