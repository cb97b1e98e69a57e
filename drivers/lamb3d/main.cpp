// lamb3d: the 3-D Lamb problem of Ding-Long-Wu section 8 by the very weak form SPH. A block
// stands for the half-space: free top face, transmitting (Lysmer-Kuhlemeyer) on the other five,
// a triangular pulse of normal traction on a square at the centre of the free surface. The
// vertical velocity at the load centre and at a surface receiver is compared with the exact
// response of the half-space (Pekeris, integrated over the square and convolved with the pulse).
//
// Cases, each one run of the same scene:
//   <variant>_<dx>   the scene's variant (method.variant: galerkin by default) at geometry.spacing
//                    (with frames) and at every other entry of study.spacings
//   published_<dx>   with study.compare_published: the scheme as printed, with the paper's filter and
//                    deconvolution, at every spacing (at the scene's spacing: the paper's Fig. 1-3)
//   strong_filter    the published scheme with study.strong_smoothing_rate (the paper's Fig. 4)
//   free_block       a larger block with all faces free (what the transmitting boundary saves)
// Writes cases.csv (errors and cost per case), <case>-probes.csv, exact.csv, frames, summary.json.
// Results: docs/studies/lamb3d.md. Plot: /usr/bin/python3 analysis/plot_lamb3d.py OUT.
//
// The same source builds lamb2d (MFWAVE_LAMB_DIMENSION = 2): the plane-strain problem with a strip
// load (data/scenes/lamb2d.toml), scored against LambStripLoad at every receiver, surface or inside
// (docs/studies/lamb2d.md).
//
// lamb2d and lamb3d also run the same scene by the spectral-element method, the seismologists'
// reference (GLL order N, elements N spacings wide, sum-factorised stiffness, dashpots on the
// transmitting faces;
// lib/studies/lamb3d/LambSpectralElementCase.hpp): --set method.name=spectral_element
// [--set method.order=4].
//   sem_n<order>_<dx>           one case per spacing (the scene's first, which also writes exact.csv)
//
// lamb2d and lamb3d also run the same scene by RK collocation (Luo-Liu-Huang strong form,
// reproducing-kernel shape functions; lib/studies/lamb3d/LambCollocationCase.hpp, one case for 2-D
// and 3-D), so that the methods meet on one problem: --set method.name=reproducing_kernel
// [--set method.order=2] [--set method.support_ratio=2.5 (lamb2d) or 2.2 (lamb3d)].
//   rk_m<order>_a<ratio>_<dx>   one case per spacing (the scene's first, which also writes exact.csv)
// The default support differs by dimension: the 3-D interior rows grow from a / h = 2.5 on (the
// mass symbol changes sign; docs/studies/stability-atlas.md), so lamb3d takes 2.2, the widest
// stable one, and refuses 2.5 at method.support_ratio. The very weak SPH's [method] keys that the
// scene sets (variant, kernel, smoothing_*, deconvolution, dashpot_lumping, ...) are accepted and
// ignored: each present one is read (so its value is still checked) and the summary names them in a
// note; nothing else in the scene needs to change. So are study.compare_published and the published /
// strong smoothing rates (no published or strong_filter case: those are the very weak SPH's);
// study.free_block_* is refused by lamb2d (the free block is a very weak SPH comparison) and read
// and ignored with a note by lamb3d, whose scene sets it. A support whose interior rows have growing
// modes is refused at method.support_ratio (exit 2) unless stability.allow_growth. The scene's
// transmitting faces are fixed for RK collocation (the case's notes say when the first reflection
// reaches a probe: in lamb3d's 7-wide block at t = 2.6, inside the error window). In 3-D a case
// costs far more than the other methods' (a sparse LU of the constraint matrix in 3-D; measured in
// docs/studies/lamb3d.md).
//
// lamb2d and lamb3d run it by the updated-Lagrangian SPH for solids too (Li's primer; a
// large-deformation method run at small amplitude, lib/studies/lamb3d/LambSolidCase.hpp, one
// implementation for D = 2 and 3): --set method.name=updated_lagrangian_sph
// [--set method.ul_viscosity_alpha=1] [--set method.ul_viscosity_beta=0] [--set method.ul_gradient_correction=true]
// [--set method.ul_tributary_volumes=true] [--set method.ul_amplitude=1e-4] (the defaults shown).
//   ulsph_<dx>   one case per spacing (the scene's first, which also writes exact.csv)
// The method's other options keep UpdatedLagrangianSphOptions' defaults (cubic spline, h / dx = 1.3,
// continuity density, no artificial stress, no XSPH; LambSolidSpec::linearDefaults): its own [method]
// keys (addUpdatedLagrangianSphKeys) share names with the very weak SPH's and cannot sit in this
// schema. The very weak SPH's keys, the published / strong cases' keys and the scene's [integrator]
// name and cfl are not used, with a note (leapfrog at the method's own step criteria). Every face is
// free (no dashpots; the notes say when the first reflection reaches a probe: t = 7.8 in lamb2d.toml,
// after the error window; t = 2.6 at the receiver in lamb3d.toml, inside it, which moves the errors
// by 0.012 at most at dx = 0.25 against the 13 x 13 x 7 free block: LambSolidCase.hpp). lamb2d
// refuses study.free_block_*; lamb3d reads and ignores it with a note, as for the spectral elements.
//
//   lamb3d --scene data/scenes/lamb3d.toml [--set 'study.spacings=[0.5]'] [--out DIR]
//   lamb2d --scene data/scenes/lamb2d.toml --set method.name=reproducing_kernel [--out DIR]

#include "studies/lamb3d/LambCase.hpp"
#include "studies/lamb3d/LambSolidSpec.hpp"

#include "core/Error.hpp"
#include "core/Interruption.hpp"
#include "integrators/ConstrainedIntegrators.hpp"
#include "io/run/CaseTable.hpp"
#include "io/run/DriverCommandLine.hpp"
#include "io/run/MemoryGuard.hpp"
#include "io/run/RunDriver.hpp"
#include "io/run/RunSummary.hpp"
#ifdef MFWAVE_WITH_MPI
#include "decomposition/mpi/MpiSession.hpp"
#include "decomposition/mpi/RankAgreement.hpp"
#include "decomposition/mpi/RankCheckpointStore.hpp"
#endif
#include "io/run/StudyCases.hpp"
#include "io/run/SceneDriver.hpp"
#include "io/scene/Format.hpp"
#include "io/scene/LoadScene.hpp"
#include "methods/spectral_element/SpectralElementElasticity.hpp"
#include "particles/BoxFace.hpp"
#include "wiring/CollocationSpec.hpp"
#include "wiring/VeryWeakSphScene.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

using namespace mfwave;
using namespace mfwave::lamb3d;

namespace {

#ifndef MFWAVE_LAMB_DIMENSION
#define MFWAVE_LAMB_DIMENSION 3
#endif
constexpr int kDimension = MFWAVE_LAMB_DIMENSION;
static_assert(kDimension == 2 || kDimension == 3, "the Lamb study is 2-D or 3-D");
const char* kProgram = kDimension == 3 ? "lamb3d" : "lamb2d";

SceneSchema lambSchema() {
  using T = ValueType;
  SceneSchema schema = SceneSchema::common();
  addVeryWeakSphKeys(schema);
  // RK collocation (lamb2d and lamb3d).
  schema.addChoice("method.name", "reproducing_kernel");
  // The spectral-element reference (lamb2d and lamb3d): method.order is its GLL order N there.
  schema.addChoice("method.name", "spectral_element");
  schema.add("method.order", T::Integer).withUnit("-")
      .defaultsToNote("2 (reproducing_kernel), 4 (spectral_element)").between(1, 8)
      .when("name = reproducing_kernel or spectral_element")
      .describedAs("RK basis order m (2 or 3: collocation needs second derivatives), or the spectral elements' GLL "
                   "order N (1 .. 8; elements N spacings wide)");
  // The default support is the one the study measured in each dimension: 2.5 in plane strain (the
  // 2-D interior grows from about 2.77), 2.2 in 3-D, where m = 2 grows from 2.5 on and 2.2 is the
  // widest stable support of the stability atlas (docs/studies/stability-atlas.md).
  schema.add("method.support_ratio", T::Number).withUnit("-").defaultsTo(kDimension == 3 ? "2.2" : "2.5").positive()
      .when("name = reproducing_kernel")
      .describedAs(kDimension == 3 ? "cubic B-spline support radius a / h (from 2.5 on the 3-D interior rows have "
                                     "growing modes: refused)"
                                   : "cubic B-spline support radius a / h (from about 2.77 on the 2-D interior rows "
                                     "have growing modes: refused)");
  // The updated-Lagrangian SPH for solids (lamb2d and lamb3d). Only what
  // the linear small-amplitude problem needs to set or to measure: the rest are the method's defaults.
  schema.addChoice("method.name", "updated_lagrangian_sph");
  schema.add("method.ul_amplitude", T::Number).withUnit("-").defaultsTo("1e-4").positive()
      .when("name = updated_lagrangian_sph")
      .describedAs("eps: the traction is eps times the scene's and the probes are divided by eps (the "
                   "large-deformation method answers the linear problem)");
  schema.add("method.ul_viscosity_alpha", T::Number).withUnit("-").defaultsTo("1.0").nonNegative()
      .when("name = updated_lagrangian_sph")
      .describedAs("Monaghan artificial viscosity alpha (1 measured best on lamb2d.toml at every spacing: it damps "
                   "the particle-scale ringing of the free surface; 0 and 0.1 ring, 2 is no better)");
  schema.add("method.ul_viscosity_beta", T::Number).withUnit("-").defaultsTo("0.0").nonNegative()
      .when("name = updated_lagrangian_sph")
      .describedAs("Monaghan artificial viscosity beta");
  schema.add("method.ul_gradient_correction", T::Boolean).defaultsTo("true").when("name = updated_lagrangian_sph")
      .describedAs("the kernel-gradient correction (Randles-Libersky) in every sum");
  schema.add("method.ul_tributary_volumes", T::Boolean).defaultsTo("true").when("name = updated_lagrangian_sph")
      .describedAs("face particles carry their tributary area (2-D: dx^2 / 2, corners dx^2 / 4) or volume (3-D: faces "
                   "dx^3 / 2, edges / 4, corners / 8); false: dx^D");
  schema.add("study", T::Table).describedAs("the cases of the lamb3d study");
  schema.add("study.spacings", T::NumberArray).withUnit("m").defaultsToNote("[geometry.spacing]")
      .describedAs("lattice spacings of the accuracy-cost cases (h scales with them; the box and load are fixed)");
  schema.add("study.error_window", T::Number).withUnit("s").defaultsTo("6.0").positive()
      .describedAs("errors are measured over 0 <= t <= error_window");
  schema.add("study.arrival_fraction", T::Number).withUnit("-").defaultsTo("0.1").between(0, 1, false, false)
      .describedAs("arrival time: first |v| >= arrival_fraction * |exact peak|");
  schema.add("study.kernel_floor", T::Boolean).defaultsTo("true")
      .describedAs("report the error the kernel's spreading of the load alone explains (exact vs kernel-smoothed exact)");
  schema.add("study.compare_published", T::Boolean).defaultsTo("true")
      .describedAs("also run the published variant (the paper's settings) at every spacing, and the figure cases");
  schema.add("study.published_smoothing_rate", T::Number).withUnit("1/s").defaultsTo("0.77").nonNegative()
      .describedAs("eq. 33 rate of the published cases (alpha = 0.1 per step at dt = 0.136)");
  schema.add("study.strong_smoothing_rate", T::Number).withUnit("1/s").defaultsTo("0.0").nonNegative()
      .describedAs("smoothing rate of the published strong_filter case (the paper's Fig. 4); 0 skips the case");
  schema.add("study.free_block_lower", T::NumberArray).withUnit("m").defaultsToNote("no free_block case")
      .describedAs("lower corner of the larger all-free block (with free_block_upper)");
  schema.add("study.free_block_upper", T::NumberArray).withUnit("m").defaultsToNote("no free_block case")
      .describedAs("upper corner of the larger all-free block");
  return schema;
}

struct Plan {
  StudySettings study;
  std::vector<CaseSettings> cases;
  std::vector<std::string> notes;  // for the summary: what the plan accepted and ignored
};

// A very weak SPH case.
CaseSettings veryWeakCase(std::string name, GeometrySpec geometry, bool freeFaces, VeryWeakSphSpec method,
                          bool writeFrames) {
  CaseSettings c;
  c.name = std::move(name);
  c.geometry = std::move(geometry);
  c.freeFaces = freeFaces;
  c.method = std::move(method);
  c.writeFrames = writeFrames;
  return c;
}

std::string caseName(const std::string& variant, Real dx) {
  std::ostringstream s;
  s << variant << '_' << dx;
  return s.str();
}

// The published scheme with the paper's settings (eq. 33 filter, deconvolution, the alpha and
// boundary corrections as the scene sets them).
VeryWeakSphSpec publishedSpec(const VeryWeakSphSpec& scene, Real rate) {
  VeryWeakSphSpec spec = scene;
  spec.options.variant = VeryWeakSphVariant::Published;
  spec.smoothingRate = rate;
  spec.smoothingOrder = 1;
  spec.smoothingScalesWithSpacing = false;
  spec.deconvolution = true;
  return spec;
}

// The spec at spacing dx: the smoothing rate scaled when the scene asks.
VeryWeakSphSpec atSpacing(VeryWeakSphSpec spec, Real dx, Real dx0) {
  spec.smoothingRate = spec.smoothingRateAt(dx, dx0);
  spec.smoothingScalesWithSpacing = false;
  return spec;
}

// The lattices of the cases: the scene's, then every other entry of study.spacings, coarsest first;
// each must divide the box.
std::vector<GeometrySpec> readGrids(SceneReader& reader, const GeometrySpec& g) {
  std::vector<GeometrySpec> grids{g};
  const std::vector<Real> spacings = reader.has("study.spacings") ? reader.numbers("study.spacings") : std::vector<Real>{};
  for (std::size_t i = 0; i < spacings.size(); ++i) {
    const Real dx = spacings[i];
    const std::string at = "study.spacings[" + std::to_string(i) + "]";
    if (!(dx > 0)) reader.fail(at, "must be positive, got " + scene::formatNumber(dx));
    if (std::abs(dx - g.spacing) <= 1e-12 * g.spacing) continue;
    try {
      grids.push_back(g.withLattice(g.lower, g.upper, dx));
    } catch (const InputError& e) {
      reader.fail(at, e.what());
    }
  }
  std::sort(grids.begin() + 1, grids.end(), [](const GeometrySpec& a, const GeometrySpec& b) { return a.spacing > b.spacing; });
  return grids;
}

// Reads each key of `paths` that the scene sets, by its schema type (so a bad value is still
// refused), and returns those it found: keys of another method or case that this plan ignores.
std::vector<std::string> readIgnoredKeys(SceneReader& reader, const std::vector<std::string>& paths) {
  std::vector<std::string> found;
  for (const std::string& path : paths) {
    if (!reader.has(path)) continue;
    switch (reader.schema().at(path).type) {
      case ValueType::Number: reader.number(path); break;
      case ValueType::Integer: reader.integer(path); break;
      case ValueType::Boolean: reader.boolean(path); break;
      case ValueType::String: reader.string(path); break;
      case ValueType::NumberArray: reader.numbers(path); break;
      default: reader.fail(path, "not used by this method");
    }
    found.push_back(path);
  }
  return found;
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

std::string collocationCaseName(const CollocationSpec& spec, Real dx) {
  std::ostringstream s;
  s << "rk_m" << spec.order << "_a" << spec.supportRatio << '_' << dx;
  return s.str();
}

// What every plan of a method other than the very weak SPH checks and says: the dimension (lamb2d
// runs them all, and so does lamb3d), one surface_patch load, no free block in lamb2d (a very weak
// SPH comparison; lamb3d's scene sets one, which the other methods read and ignore with a note: they
// run the scene's box, LambSolidCase.hpp and LambCollocationCase.hpp say what its faces cost), and
// the very weak SPH's and the published / strong cases' keys the scene sets, read (still checked)
// and ignored with a note. `method` is the method.name, `label` how the messages name it.
void readOtherMethodPlan(SceneReader& reader, Plan& plan, const std::string& method, const std::string& label) {
  const Scene& scene = plan.study.scene;
  if (scene.loads.size() != 1 || scene.loads[0].type != LoadType::SurfacePatch)
    reader.fail("load", label + " in " + std::string(kProgram) + " needs exactly one surface_patch load");
  if (kDimension == 3) {
    const std::vector<std::string> block = readIgnoredKeys(reader, {"study.free_block_lower", "study.free_block_upper"});
    if (!block.empty())
      plan.notes.push_back(method + " runs no free_block case (a very weak SPH comparison); ignored: " + joined(block));
  } else if (reader.has("study.free_block_lower") || reader.has("study.free_block_upper"))
    reader.fail(reader.has("study.free_block_lower") ? "study.free_block_lower" : "study.free_block_upper",
                "the free_block case compares the very weak SPH's transmitting faces; " + label +
                    " runs none (remove study.free_block_*)");
  const std::vector<std::string> ignoredMethod = readIgnoredKeys(reader, veryWeakSphOptionKeys(reader.schema()));
  if (!ignoredMethod.empty())
    plan.notes.push_back(method + " ignores the very weak SPH's keys the scene sets: " + joined(ignoredMethod));
  const std::vector<std::string> ignoredStudy = readIgnoredKeys(
      reader, {"study.compare_published", "study.published_smoothing_rate", "study.strong_smoothing_rate"});
  if (!ignoredStudy.empty())
    plan.notes.push_back(method + " runs no published or strong_filter case; ignored: " + joined(ignoredStudy));
}

// The RK collocation plan (lamb2d or lamb3d, method.name = reproducing_kernel): one case per
// spacing, the scene's first (with exact.csv).
void readCollocationPlan(SceneReader& reader, Plan& plan) {
  const Scene& scene = plan.study.scene;
  readOtherMethodPlan(reader, plan, "reproducing_kernel", "RK collocation");
  const CollocationSpec spec = readCollocationSpec(reader, scene.method.name, kProgram);
  const std::vector<std::string> integrators = constrainedIntegratorNames();
  if (std::find(integrators.begin(), integrators.end(), scene.integrator.name) == integrators.end())
    reader.fail("integrator.name", "RK collocation runs central_difference or newmark");
  for (std::size_t i = 0; i < scene.boundaries.size(); ++i)
    if ((scene.boundaries[i].faceMask & faceBit(scene.loads[0].face)) != 0)
      reader.fail("boundary[" + std::to_string(i) + "].faces",
                  "RK collocation needs the loaded face free: its traction rows carry the load");
  // Growing interior modes grow at every step: refused here, before any work, naming the key.
  const CollocationGrowingModes modes =
      rkGrowingModes(kDimension, spec.order, spec.supportRatio, scene.material.material());
  if (modes.growing()) {
    if (!scene.stability.allowGrowth)
      reader.fail("method.support_ratio", modes.what + "; " + modes.advice +
                                              ", or stability.allow_growth = true runs it on purpose");
    plan.notes.push_back("stability.allow_growth: ran although " + modes.what);
  }
  const std::vector<GeometrySpec> grids = readGrids(reader, scene.geometry);
  // In 3-D the sparse LU of the constraint matrix fills fast: the peak memory, measured on
  // lamb3d.toml at a / h = 2.2, went from 254 MiB (3375 nodes) to 4167 MiB (24,389 nodes), about
  // nodes^1.41. A case that would need more than the machine has by that law (dx = 0.125: about
  // 71 GiB) is refused before any case runs.
  if (kDimension == 3) {
    const double machine = physicalMemoryMiB();
    for (const GeometrySpec& g : grids) {
      const double nodes = static_cast<double>(g.particleCount());
      const double need = 4167.0 * std::pow(nodes / 24389.0, 1.41);
      if (need > machine)
        reader.fail(g.spacing == scene.geometry.spacing ? "geometry.spacing" : "study.spacings",
                    "RK collocation at dx = " + scene::formatNumber(g.spacing) + " (" +
                        std::to_string(g.particleCount()) + " nodes) needs about " +
                        scene::formatNumber(std::round(need / 1024.0)) + " GiB for the LU of its constraint "
                        "matrix (measured 4.1 GiB at 24,389 nodes, growing as nodes^1.41); this machine has " +
                        scene::formatNumber(std::round(machine / 1024.0)) +
                        " GiB (run coarser spacings, e.g. --set 'study.spacings=[0.5]')");
    }
  }
  for (std::size_t i = 0; i < grids.size(); ++i) {
    CaseSettings c;
    c.name = collocationCaseName(spec, grids[i].spacing);
    c.geometry = grids[i];
    c.writeFrames = i == 0;
    c.collocation = spec;
    plan.cases.push_back(c);
  }
}

// The updated-Lagrangian SPH plan (lamb2d and lamb3d, method.name = updated_lagrangian_sph): one case
// per spacing on the scene's box, the scene's spacing first (with exact.csv).
void readSolidPlan(SceneReader& reader, Plan& plan) {
  const Scene& scene = plan.study.scene;
  readOtherMethodPlan(reader, plan, "updated_lagrangian_sph", "the updated-Lagrangian SPH");
  LambSolidSpec spec = LambSolidSpec::linearDefaults(scene.material.material());
  spec.options.viscosity.alpha = reader.number("method.ul_viscosity_alpha");
  spec.options.viscosity.beta = reader.number("method.ul_viscosity_beta");
  spec.options.kernelGradientCorrection = reader.boolean("method.ul_gradient_correction");
  spec.amplitude = reader.number("method.ul_amplitude");
  spec.tributaryVolumes = reader.boolean("method.ul_tributary_volumes");
  if (spec.amplitude > 0.01)
    reader.fail("method.ul_amplitude", "is " + scene::formatNumber(spec.amplitude) +
                                           ": above 0.01 the strains are no longer small and the case no longer "
                                           "answers the linear problem it is scored against");
  plan.notes.push_back("updated_lagrangian_sph steps by leapfrog at the method's own step criteria (0.3 h / (c_p "
                       "(1 + 1.2 alpha)) and the force criterion, recomputed every step); the scene's "
                       "integrator.name = " + scene.integrator.name + " and its cfl are not used");

  const std::vector<GeometrySpec> grids = readGrids(reader, scene.geometry);
  for (std::size_t i = 0; i < grids.size(); ++i) {
    CaseSettings c;
    c.name = caseName("ulsph", grids[i].spacing);
    c.geometry = grids[i];
    c.writeFrames = i == 0;
    c.solid = spec;
    plan.cases.push_back(c);
  }
}

std::string spectralElementCaseName(int order, Real dx) {
  std::ostringstream s;
  s << "sem_n" << order << '_' << dx;
  return s.str();
}


// The spectral-element plan (lamb2d or lamb3d, method.name = spectral_element): one case per spacing, elements
// method.order spacings wide, the scene's spacing first (with exact.csv).
void readSpectralElementPlan(SceneReader& reader, Plan& plan) {
  const Scene& scene = plan.study.scene;
  readOtherMethodPlan(reader, plan, "spectral_element", "the spectral-element reference");
  const int order = static_cast<int>(reader.integer("method.order", 4));
  if (scene.integrator.kind != IntegratorKind::CentralDifference)
    reader.fail("integrator.name", "the spectral-element reference runs central_difference (its lumped mass makes "
                                   "it explicit)");
  for (std::size_t i = 0; i < scene.boundaries.size(); ++i) {
    const BoundaryType type = scene.boundaries[i].type;
    if (type != BoundaryType::Free && type != BoundaryType::Fixed && type != BoundaryType::Transmitting)
      reader.fail("boundary[" + std::to_string(i) + "].type",
                  "the spectral-element case runs free, fixed and transmitting faces");
  }
  const LoadSpec& load = scene.loads[0];
  const auto normal = static_cast<std::size_t>(faceAxis(load.face));
  const std::vector<GeometrySpec> grids = readGrids(reader, scene.geometry);
  for (std::size_t i = 0; i < grids.size(); ++i) {
    const GeometrySpec& g = grids[i];
    const std::string key = i == 0 ? "geometry.spacing" : "study.spacings";
    const Real size = order * g.spacing;
    for (std::size_t a = 0; a < static_cast<std::size_t>(kDimension); ++a)
      if (wholeElements(g.upper[a] - g.lower[a], size) < 0)
        reader.fail(key, "spectral elements of order " + std::to_string(order) + " at spacing " +
                             scene::formatNumber(g.spacing) + " are " + scene::formatNumber(size) +
                             " wide, which does not divide the box " + g.describeBox() +
                             " (choose a spacing or method.order whose product divides it)");
    // The load's edges inside elements: the load vector is still exact, but the degree-N trace
    // cannot follow the load's jump there (said, not refused: the coarsest study case has them).
    bool noted = false;
    for (std::size_t along = 0; along < static_cast<std::size_t>(kDimension) && !noted; ++along) {
      if (along == normal) continue;
      for (const Real end : {load.centre[along] - load.halfWidth[along], load.centre[along] + load.halfWidth[along]})
        if (end > g.lower[along] && wholeElements(end - g.lower[along], size) < 0) {
          plan.notes.push_back(spectralElementCaseName(order, g.spacing) + ": the loaded " +
                               (kDimension == 2 ? "strip's end " : "square's edge ") + scene::formatNumber(end) +
                               " falls inside an element " + scene::formatNumber(size) +
                               " wide (its load vector is integrated exactly on the loaded part of the face)");
          noted = true;
          break;
        }
    }
    CaseSettings c;
    c.name = spectralElementCaseName(order, g.spacing);
    c.geometry = g;
    c.writeFrames = i == 0;
    c.spectralElementOrder = order;
    plan.cases.push_back(c);
  }
}

// The UL-SPH and spectral-element cases that need more memory than the machine has, refused before
// any case runs (measured in the tradeoff sweep: the UL-SPH 1.4 KiB per particle in 2-D and 2.6 KiB in
// 3-D, plus its per-evaluation pair table, 0.6 and 2.4 KiB (bench_updated_lagrangian_sph at 1e6); the
// spectral elements 0.5 KiB per node; with a margin).
void refuseCasesBeyondMemory(SceneReader& reader, const Plan& plan) {
  for (const CaseSettings& c : plan.cases) {
    MemoryEstimate estimate;
    estimate.particles = static_cast<double>(c.geometry.particleCount());
    if (c.isSolid()) {
      estimate.bytesPerParticle = kDimension == 3 ? 8192 : 3072;
      estimate.basis = kDimension == 3 ? "the UL-SPH in 3-D, 5.0 KiB: 2.6 KiB measured and its pair table"
                                       : "the UL-SPH in 2-D, 2.0 KiB: 1.4 KiB measured and its pair table";
    } else if (c.isSpectralElement()) {
      estimate.bytesPerParticle = 1024;
      estimate.basis = "the spectral elements, 0.5 KiB per node measured";
    } else {
      continue;
    }
    const std::string why = memoryRefusal("case " + c.name + " (dx = " + scene::formatNumber(c.geometry.spacing) + ")", estimate);
    if (!why.empty())
      reader.fail(c.geometry.spacing == plan.study.scene.geometry.spacing ? "geometry.spacing" : "study.spacings", why);
  }
}

Plan readPlan(SceneReader& reader) {
  Plan plan;
  StudySettings& study = plan.study;
  study.scene = readScene(reader);
  const Scene& scene = study.scene;
  if (scene.info.dimension != kDimension)
    reader.fail("scene.dimension", std::string(kProgram) + " is a " + std::to_string(kDimension) + "-D study");
  study.errorWindow = reader.number("study.error_window");
  study.arrivalFraction = reader.number("study.arrival_fraction");
  study.kernelFloor = reader.boolean("study.kernel_floor");
  if (scene.method.name == "reproducing_kernel") {
    readCollocationPlan(reader, plan);
    return plan;
  }
  if (scene.method.name == "updated_lagrangian_sph") {
    readSolidPlan(reader, plan);
    refuseCasesBeyondMemory(reader, plan);
    return plan;
  }
  if (scene.method.name == "spectral_element") {
    readSpectralElementPlan(reader, plan);
    refuseCasesBeyondMemory(reader, plan);
    return plan;
  }
  if (scene.method.name != "very_weak_sph")
    reader.fail("method.name", std::string(kProgram) + " runs the very_weak_sph method" +
                                   ", reproducing_kernel, updated_lagrangian_sph or spectral_element");
  const VeryWeakSphSpec main = readVeryWeakSph(reader, scene.material.material());
  const bool comparePublished = reader.boolean("study.compare_published") && main.options.variant != VeryWeakSphVariant::Published;
  const VeryWeakSphSpec published = publishedSpec(main, reader.number("study.published_smoothing_rate"));
  const Real strong = reader.number("study.strong_smoothing_rate");

  // Spacings, the scene's first; each must divide the box.
  const GeometrySpec& g = scene.geometry;
  const std::vector<GeometrySpec> grids = readGrids(reader, g);
  // At the scene's spacing: the main variant (with frames), the published figure cases, the free
  // block; then every other spacing, for each variant, cheapest first.
  plan.cases.push_back(
      veryWeakCase(caseName(main.variantName(), g.spacing), g, false, atSpacing(main, g.spacing, g.spacing), true));
  if (comparePublished)
    plan.cases.push_back(veryWeakCase(caseName("published", g.spacing), g, false, published, false));
  if (strong > 0 && (comparePublished || main.options.variant == VeryWeakSphVariant::Published)) {
    VeryWeakSphSpec strongSpec = main.options.variant == VeryWeakSphVariant::Published ? atSpacing(main, g.spacing, g.spacing) : published;
    strongSpec.smoothingRate = strong;
    plan.cases.push_back(veryWeakCase("strong_filter", g, false, strongSpec, false));
  }
  if (reader.has("study.free_block_lower") || reader.has("study.free_block_upper")) {
    const std::vector<Real> lower = reader.numbers("study.free_block_lower", kDimension);
    const std::vector<Real> upper = reader.numbers("study.free_block_upper", kDimension);
    for (std::size_t a = 0; a < static_cast<std::size_t>(kDimension); ++a)
      if (lower[a] > g.lower[a] || upper[a] < g.upper[a])
        reader.fail("study.free_block_lower", "the free block must contain the scene's box " + g.describeBox());
    try {
      plan.cases.push_back(veryWeakCase("free_block", g.withLattice(lower, upper, g.spacing), true,
                                        atSpacing(main, g.spacing, g.spacing), false));
    } catch (const InputError& e) {
      reader.fail("study.free_block_upper", e.what());
    }
  }
  for (std::size_t i = 1; i < grids.size(); ++i) {
    const Real dx = grids[i].spacing;
    plan.cases.push_back(
        veryWeakCase(caseName(main.variantName(), dx), grids[i], false, atSpacing(main, dx, g.spacing), false));
    if (comparePublished)
      plan.cases.push_back(veryWeakCase(caseName("published", dx), grids[i], false, published, false));
  }
  // Every case's combination of variant, filter, deconvolution, faces and integrator, before any work.
  for (const CaseSettings& c : plan.cases) checkVeryWeakSphScene(reader, scene, c.method, kProgram);
  // A case that needs more memory than the machine has is refused before any case runs: a whole
  // run holds about 6.7 KiB per particle with the sparse matrices, 8 KiB with the ghosts and a
  // margin, and about 200 bytes with the lattice stencils, 320 with a margin (docs/performance.md).
  const double machine = physicalMemoryMiB();
  for (const CaseSettings& c : plan.cases) {
    const bool lattice =
        veryWeakSphProblemSettings<kDimension>(scene, c.geometry, c.method, !c.freeFaces).storage ==
        OperatorStorage::Lattice;
    const double bytes = lattice ? 320.0 : 8192.0;
    const double need = bytes / (1024.0 * 1024.0) * static_cast<double>(c.geometry.particleCount());
    if (need > machine)
      reader.fail(c.geometry.spacing == g.spacing ? "geometry.spacing" : "study.spacings",
                  "case " + c.name + " (dx = " + scene::formatNumber(c.geometry.spacing) + ") needs about " +
                      scene::formatNumber(std::round(need / 1024.0)) + " GiB (" +
                      std::to_string(c.geometry.particleCount()) + " particles at about " +
                      scene::formatNumber(bytes) + " bytes each, " + (lattice ? "lattice stencils" : "sparse matrices") +
                      "); this machine has " + scene::formatNumber(std::round(machine / 1024.0)) + " GiB");
  }
  return plan;
}

// cases.csv and the terminal table, one column each; a group of columns per probe (the probes are
// the same in every case).
CaseTable<CaseResult> casesTable(const std::vector<ProbeResult>& probes) {
  using R = const CaseResult&;
  CaseTable<CaseResult> t;
  // The very weak SPH's own figures are blank for an RK collocation case; its variant column says
  // "rk m=<order> a/h=<ratio>", mean_neighbours counts the nodes per collocation point and
  // operator_nonzeros those of the collocation matrix A. An updated-Lagrangian SPH case says
  // "ul-sph alpha=<a> beta=<b>", fills h and mean_neighbours (of its last evaluation), its
  // stable_step_estimate is the method's step at t = 0 and its dt the mean step; it has no operator.
  // A spectral-element case ("sem N=<order>") fills particles (GLL nodes), operator_nonzeros (its one
  // element matrix), the Gershgorin step and the energy ledger.
  const auto veryWeakOnly = [](R r, TableCell value) { return r.settings.isVeryWeakSph() ? value : TableCell(); };
  const auto notSolid = [](R r, TableCell value) { return r.settings.isSolid() ? TableCell() : value; };
  const auto withLedger = [](R r, TableCell value) {
    return r.settings.isVeryWeakSph() || r.settings.isSpectralElement() ? value : TableCell();
  };
  t.column("case", [](R r) { return r.settings.name; }, TerminalColumn("case", 16).left())
      .column("variant", [](R r) { return r.settings.methodLabel(); })
      .column("smoothing_rate [1/s]", [veryWeakOnly](R r) { return veryWeakOnly(r, r.settings.method.smoothingRate); })
      .column("spacing [m]", [](R r) { return r.settings.geometry.spacing; }, TerminalColumn("dx", 8))
      .column("h [m]", [](R r) {
        return r.settings.isVeryWeakSph() || r.settings.isSolid() ? TableCell(r.smoothingLength) : TableCell();
      })
      .column("particles", [](R r) { return r.record.particles; }, TerminalColumn("particles", 10))
      .column("ghosts", [veryWeakOnly](R r) { return veryWeakOnly(r, r.ghosts); })
      .column("mean_neighbours", [](R r) { return r.meanNeighbours; })
      .column("operator_nonzeros", [notSolid](R r) { return notSolid(r, r.operatorNonZeros); })
      .column("operator [MiB]", [veryWeakOnly](R r) { return veryWeakOnly(r, r.operatorMiB); })
      .column("stable_step_estimate [s]", [](R r) { return r.record.stableTimeStep; })
      .column("stable_step_gershgorin [s]", [withLedger](R r) { return withLedger(r, r.stableStepGershgorin); })
      .column("dt [s]", [](R r) { return r.record.timeStep; }, TerminalColumn("dt", 9))
      .column("steps", [](R r) { return r.record.steps; }, TerminalColumn("steps", 7))
      .column("assembly [s]", [](R r) { return r.record.setupSeconds; })
      .column("run [s]", [](R r) { return r.record.loopSeconds; })
      .column("wall [s]", [](R r) { return r.record.setupSeconds + r.record.loopSeconds; }, TerminalColumn("wall[s]", 9).precision(3))
      .column("peak_memory [MiB]", [](R r) { return r.record.peakMemoryMiB; }, TerminalColumn("MiB", 9))
      // the whole process's peak over the physical particles (issue 18's measure; includes the
      // exact reference and everything earlier cases left)
      .column("peak_memory_bytes_per_particle",
              [](R r) { return r.record.peakMemoryMiB * 1048576.0 / static_cast<Real>(r.record.particles); })
      .column("particle_steps_per_second", [](R r) { return r.record.particleStepsPerSecond(); })
      .column("energy_final_fraction", [withLedger](R r) { return withLedger(r, r.energyFinalFraction); })
      .column("energy_balance_drift", [withLedger](R r) { return withLedger(r, r.energyBalanceDrift); });
  for (std::size_t k = 0; k < probes.size(); ++k)
    for (const bool reported : {false, true}) {
      const std::string stem = probes[k].name + (reported ? "_reported" : "_raw");
      const auto errors = [k, reported](R r) -> const SignalErrors& {
        return reported ? r.probes[k].reported : r.probes[k].raw;
      };
      t.column(stem + "_relative_l2", [k, errors](R r) { return cellIf(r.probes[k].hasExact, errors(r).relativeL2); })
          .column(stem + "_peak_error", [k, errors](R r) { return cellIf(r.probes[k].hasExact, errors(r).peakError); })
          .column(stem + "_arrival_error [s]",
                  [k, errors](R r) { return cellIf(r.probes[k].hasExact, errors(r).arrivalError); });
    }
  for (std::size_t k = 0; k < probes.size(); ++k)
    t.column(probes[k].name + "_kernel_floor_relative_l2", [k](R r) { return r.probes[k].kernelFloor; });
  // The terminal's probe columns: reported / raw L2, and the reported peak error.
  for (std::size_t k = 0; k < probes.size(); ++k)
    t.terminalOnly(TerminalColumn(probes[k].name + " L2", 14),
                   [k](R r) -> TableCell {
                     const ProbeResult& p = r.probes[k];
                     if (!p.hasExact) return std::string("-");
                     std::ostringstream l2;
                     l2 << std::setprecision(3) << p.reported.relativeL2 << '/' << p.raw.relativeL2;
                     return l2.str();
                   })
        .terminalOnly(TerminalColumn("peak", 9).precision(3), [k](R r) {
          return r.probes[k].hasExact ? r.probes[k].reported.peakError : std::nan("");
        });
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  const SceneSchema schema = lambSchema();
  DriverCommandLine cli(kProgram,
                        kDimension == 3
                            ? "lamb3d: the Ding-Long-Wu 3-D Lamb problem by very weak form SPH, RK collocation, "
                              "updated-Lagrangian SPH or "
                              "spectral elements, against the exact response"
                            : "lamb2d: the plane-strain Lamb problem (a strip load) by very weak form SPH, RK "
                              "collocation, updated-Lagrangian SPH or spectral elements, against the exact response",
                        schema.describe());
#ifdef MFWAVE_WITH_MPI
  // Under mpirun the very weak SPH cases step on the ranks (LambRankCase.hpp); rank 0 reports and
  // writes. A plain run starts no MPI.
  const MpiSession mpi(argc, argv);
  const int rank = MpiSession::rank();
#else
  const int rank = 0;
#endif
  if (const auto exit = cli.parse(argc, argv)) return *exit;

  const int code = runDriver(kProgram, [&]() -> int {
    SceneReader reader = loadDriverScene(cli.options(), schema);
    const Plan plan = readPlan(reader);
    reader.checkAllKeysRead();
#ifdef MFWAVE_WITH_MPI
    const CheckpointStoreMaker storeMaker = rankAwareCheckpointStoreMaker();  // per rank on several ranks
#else
    const CheckpointStoreMaker storeMaker;
#endif
    const std::string folder = prepareOutputFolder(cli.options(), plan.study.scene.output.folder, reader, storeMaker);

    const bool progress = !cli.options().quiet && rank == 0;
#ifdef MFWAVE_WITH_MPI
    // Cases run on rank 0 alone too: the ranks agree between cases whether a signal stops the study.
    const TimeLoop::Agreement caseAgreement =
        MpiSession::size() > 1 ? maximumOverRanks(MPI_COMM_WORLD) : TimeLoop::Agreement();
#else
    const TimeLoop::Agreement caseAgreement;
#endif
    const std::vector<CaseResult> results = runCases(
        plan.cases, [&](const CaseSettings& settings) { return runCase(plan.study, settings, folder, progress); },
        progress, caseAgreement);
    if (rank != 0) return 0;  // rank 0 reports and writes the run's tables
    const CaseTable<CaseResult> table = casesTable(results.front().probes);
    table.writeCsv(folder + "/cases.csv", results, 8);
    std::cout << "(probe L2: reported / raw; reported = deconvolved for the published variant)\n";
    table.print(std::cout, results);

    const CaseResult& paper = results.front();  // the scene's variant at its spacing
    const Scene& scene = plan.study.scene;
    // The updated-Lagrangian SPH steps by leapfrog whatever the scene's [integrator] says (readSolidPlan).
    RunSummary summary(kProgram, scene.info.name, scene.method.name,
                       paper.settings.isSolid() ? std::string("leapfrog") : scene.integrator.name);
    summary.files.add("cases.csv");
    summary.addCases(results);
    summary.totalsFromFirstCase();
    summary.meanNeighbours = paper.meanNeighbours;
    for (const CaseResult& r : results)
      for (const ProbeResult& p : r.probes) {
        if (!p.hasExact) continue;
        const std::string stem = r.settings.name + "_" + p.name;
        summary.errors.push_back({stem + "_relative_l2", p.reported.relativeL2});
        if (r.settings.isVeryWeakSph() && r.settings.method.deconvolution)
          summary.errors.push_back({stem + "_relative_l2_raw", p.raw.relativeL2});
        summary.errors.push_back({stem + "_peak_error", p.reported.peakError});
        summary.errors.push_back({stem + "_arrival_error [s]", p.reported.arrivalError});
        if (std::isfinite(p.kernelFloor)) summary.figures.push_back({stem + "_kernel_floor", p.kernelFloor});
      }
    for (const CaseResult& r : results) {
      summary.figures.push_back({r.settings.name + "_stable_step_estimate", r.record.stableTimeStep});
      summary.figures.push_back({r.settings.name + "_particle_steps_per_second", r.record.particleStepsPerSecond()});
      if (r.settings.isCollocation() || r.settings.isSolid()) continue;  // no energy ledger
      summary.figures.push_back({r.settings.name + "_energy_final_fraction", r.energyFinalFraction});
      summary.figures.push_back({r.settings.name + "_energy_balance_drift", r.energyBalanceDrift});
    }
    summary.notes.add("particles, neighbours and dt of the first case (" + paper.settings.name +
                      "); steps and wall time summed over " + std::to_string(results.size()) + " cases");
    summary.notes.addAll(plan.notes);
    summary.mergeNotesAndFiles(results);
    summary.conclude(folder, &std::cout);
    return 0;
  }, rank);
#ifdef MFWAVE_WITH_MPI
  // A rank that failed must not leave the others waiting in a halo exchange.
  // An agreed interruption (130, 143) is no failure: every rank stops at the same step and rank 0
  // writes its tables; only then do they exit.
  if (code != 0 && !interruptionRequested()) MpiSession::abortOthers(code);
#endif
  return code;
}
