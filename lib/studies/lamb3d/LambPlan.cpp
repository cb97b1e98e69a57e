#include "studies/lamb3d/LambPlan.hpp"

#include "catalogue/MethodCatalogue.hpp"
#include "catalogue/SceneSupport.hpp"
#include "core/Error.hpp"
#include "integrators/ConstrainedIntegrators.hpp"
#include "io/run/MemoryGuard.hpp"
#include "io/run/RunSummary.hpp"
#include "io/scene/Format.hpp"
#include "methods/spectral_element/SpectralElementElasticity.hpp"
#include "particles/BoxFace.hpp"
#include "studies/lamb3d/LambSolidSpec.hpp"
#include "wiring/CollocationSpec.hpp"
#include "wiring/UpdatedLagrangianSphSpec.hpp"
#include "wiring/VeryWeakSphScene.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mfwave::lamb3d {
namespace {

// The plan of the study in D dimensions; every reader a member, so that the dimension and the
// program's name are the class's.
template <int D>
struct PlanReader {
  static constexpr int kDimension = D;
  static constexpr const char* kProgram = D == 3 ? "lamb3d" : "lamb2d";

  static SceneSchema lambSchema() {
    using T = ValueType;
    SceneSchema schema = SceneSchema::common();
    addVeryWeakSphKeys(schema);
    // method.name: the catalogue's methods that name this study among their programs.
    for (const std::string& name : lambMethods(D))
      if (name != "very_weak_sph") schema.addChoice("method.name", name);
    // RK collocation's keys (their one declaration, lib/wiring/CollocationSpec) with the support the
    // study measured in each dimension: 2.5 in plane strain (the 2-D interior grows from about 2.77),
    // 2.2 in 3-D, where m = 2 grows from 2.5 on and 2.2 is the widest stable support of the stability
    // atlas (docs/studies/stability-atlas.md).
    CollocationKeyDefaults collocation;
    collocation.supportRatio = kDimension == 3 ? 2.2 : 2.5;
    collocation.supportAdvice = kDimension == 3 ? "from 2.5 on the 3-D interior rows have growing modes: refused"
                                                : "from about 2.77 on the 2-D interior rows have growing modes: refused";
    addCollocationKeys(schema, collocation);
    // method.order is the spectral elements' GLL order N too: no one default, and N up to 8 (the RK
    // range is checked by readCollocationSpec).
    KeySpec& order = schema.at("method.order");
    order.defaultLiteral.clear();
    order.defaultsToNote("2 (reproducing_kernel), 4 (spectral_element)").between(1, 8)
        .when("name = reproducing_kernel or spectral_element")
        .describedAs("RK basis order m (2 or 3: collocation needs second derivatives), or the spectral elements' GLL "
                     "order N (1 .. 8; elements N spacings wide)");
    // The updated-Lagrangian SPH for solids (lamb2d and lamb3d). Only what
    // the linear small-amplitude problem needs to set or to measure: the rest are the method's defaults.
    schema.add("method.ul_amplitude", T::Number).withUnit("-").defaultsTo("1e-4").positive()
        .when("name = updated_lagrangian_sph")
        .describedAs("eps: the traction is eps times the scene's and the probes are divided by eps (the "
                     "large-deformation method answers the linear problem)");
    // The method's own viscosity and gradient-correction keys, with the defaults this problem needs:
    // alpha 1 (measured best on lamb2d.toml at every spacing: it damps the particle-scale ringing of
    // the free surface; 0 and 0.1 ring, 2 is no better) and the kernel-gradient correction on.
    addUpdatedLagrangianSphViscosityKeys(schema, smallAmplitudeWaveDefaults());
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


  // A very weak SPH case.
  static CaseSettings veryWeakCase(std::string name, GeometrySpec geometry, bool freeFaces, VeryWeakSphSpec method,
                            bool writeFrames) {
    CaseSettings c;
    c.name = std::move(name);
    c.geometry = std::move(geometry);
    c.freeFaces = freeFaces;
    c.method = std::move(method);
    c.writeFrames = writeFrames;
    return c;
  }

  static std::string caseName(const std::string& variant, Real dx) {
    std::ostringstream s;
    s << variant << '_' << dx;
    return s.str();
  }

  // The published scheme with the paper's settings (eq. 33 filter, deconvolution, the alpha and
  // boundary corrections as the scene sets them).
  static VeryWeakSphSpec publishedSpec(const VeryWeakSphSpec& scene, Real rate) {
    VeryWeakSphSpec spec = scene;
    spec.options.variant = VeryWeakSphVariant::Published;
    spec.smoothingRate = rate;
    spec.smoothingOrder = 1;
    spec.smoothingScalesWithSpacing = false;
    spec.deconvolution = true;
    return spec;
  }

  // The spec at spacing dx: the smoothing rate scaled when the scene asks.
  static VeryWeakSphSpec atSpacing(VeryWeakSphSpec spec, Real dx, Real dx0) {
    spec.smoothingRate = spec.smoothingRateAt(dx, dx0);
    spec.smoothingScalesWithSpacing = false;
    return spec;
  }

  // The lattices of the cases: the scene's, then every other entry of study.spacings, coarsest first;
  // each must divide the box.
  static std::vector<GeometrySpec> readGrids(SceneReader& reader, const GeometrySpec& g) {
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
  static std::vector<std::string> readIgnoredKeys(SceneReader& reader, const std::vector<std::string>& paths) {
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

  static std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
  }

  static std::string collocationCaseName(const CollocationSpec& spec, Real dx) {
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
  static void readOtherMethodPlan(SceneReader& reader, Plan& plan, const std::string& method, const std::string& label) {
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
  static void readCollocationPlan(SceneReader& reader, Plan& plan) {
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
  static void readSolidPlan(SceneReader& reader, Plan& plan) {
    const Scene& scene = plan.study.scene;
    readOtherMethodPlan(reader, plan, "updated_lagrangian_sph", "the updated-Lagrangian SPH");
    LambSolidSpec spec = LambSolidSpec::linearDefaults(scene.material.material());
    spec.options.viscosity.alpha = reader.number("method.viscosity_alpha");
    spec.options.viscosity.beta = reader.number("method.viscosity_beta");
    spec.options.kernelGradientCorrection = reader.boolean("method.kernel_gradient_correction");
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
    refuseCasesBeyondMemory(reader, plan);
  }

  static std::string spectralElementCaseName(int order, Real dx) {
    std::ostringstream s;
    s << "sem_n" << order << '_' << dx;
    return s.str();
  }


  // The spectral-element plan (lamb2d or lamb3d, method.name = spectral_element): one case per spacing, elements
  // method.order spacings wide, the scene's spacing first (with exact.csv).
  static void readSpectralElementPlan(SceneReader& reader, Plan& plan) {
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
    refuseCasesBeyondMemory(reader, plan);
  }

  // The UL-SPH and spectral-element cases that need more memory than the machine has, refused before
  // any case runs (measured in the tradeoff sweep: the UL-SPH 1.4 KiB per particle in 2-D and 2.6 KiB in
  // 3-D, plus its per-evaluation pair table, 0.6 and 2.4 KiB (bench_updated_lagrangian_sph at 1e6); the
  // spectral elements 0.5 KiB per node; with a margin).
  static void refuseCasesBeyondMemory(SceneReader& reader, const Plan& plan) {
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

  static Plan readPlan(SceneReader& reader) {
    Plan plan;
    StudySettings& study = plan.study;
    study.scene = readScene(reader);
    const Scene& scene = study.scene;
    if (scene.info.dimension != kDimension)
      reader.fail("scene.dimension", std::string(kProgram) + " is a " + std::to_string(kDimension) + "-D study");
    study.errorWindow = reader.number("study.error_window");
    study.arrivalFraction = reader.number("study.arrival_fraction");
    study.kernelFloor = reader.boolean("study.kernel_floor");
    // One reader per method of the catalogue that runs in this study (lambMethods; a test checks
    // that every one has its reader).
    using Reader = void (*)(SceneReader&, Plan&);
    static const std::pair<const char*, Reader> readers[] = {{"very_weak_sph", readVeryWeakPlan},
                                                             {"reproducing_kernel", readCollocationPlan},
                                                             {"updated_lagrangian_sph", readSolidPlan},
                                                             {"spectral_element", readSpectralElementPlan}};
    for (const auto& [name, read] : readers)
      if (scene.method.name == name) {
        // A boundary the method cannot represent (a symmetry plane for a method without one), by the
        // catalogue's word, before its own reader (which judges the rest: the UL-SPH, for one, runs
        // a second-order scene's integrator as leapfrog).
        for (const UnsupportedFeature& f : unsupportedFeatures(scene, methodNamed(name)))
          if (f.key.rfind("boundary[", 0) == 0) reader.fail(f.key, f.message());
        read(reader, plan);
        return plan;
      }
    reader.fail("method.name", std::string(kProgram) + " runs " + scene::joinNames(lambMethods(D)) +
                                   " (mfwave methods lists what each supports)");
  }

  // The very weak SPH plan: the scene's variant at every spacing, with the published comparison,
  // the strong filter and the free block where the scene asks.
  static void readVeryWeakPlan(SceneReader& reader, Plan& plan) {
    const Scene& scene = plan.study.scene;
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
      // It is the same solid's larger block: on the scene's side of its symmetry planes.
      const std::uint8_t symmetry = facesWith(scene.boundaries, BoundaryType::Symmetry);
      for (std::size_t a = 0; a < static_cast<std::size_t>(kDimension); ++a)
        if (((symmetry & faceBit(2 * static_cast<int>(a))) != 0 && lower[a] != g.lower[a]) ||
            ((symmetry & faceBit(2 * static_cast<int>(a) + 1)) != 0 && upper[a] != g.upper[a]))
          reader.fail((symmetry & faceBit(2 * static_cast<int>(a))) != 0 ? "study.free_block_lower" : "study.free_block_upper",
                      std::string("must share the symmetry plane of axis ") + axisName(static_cast<int>(a)) +
                          " with the scene's box " + g.describeBox());
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
  }
};

}  // namespace

const char* lambProgram(int dimension) { return dimension == 3 ? "lamb3d" : "lamb2d"; }

std::vector<std::string> lambMethods(int dimension) { return methodsRunBy(lambProgram(dimension)); }

SceneSchema lambSchema(int dimension) {
  return dimension == 3 ? PlanReader<3>::lambSchema() : PlanReader<2>::lambSchema();
}

template <int D>
Plan readLambPlan(SceneReader& reader) {
  return PlanReader<D>::readPlan(reader);
}

template Plan readLambPlan<2>(SceneReader&);
template Plan readLambPlan<3>(SceneReader&);

}  // namespace mfwave::lamb3d
