#include "studies/solid/SolidStudy.hpp"

#include "studies/solid/SolidCase.hpp"

#include "analytic/LambStripLoad.hpp"
#include "catalogue/MethodCatalogue.hpp"
#include "catalogue/SceneSupport.hpp"
#include "core/Error.hpp"
#include "core/Stopwatch.hpp"
#include "integrators/IntegratorFactory.hpp"
#include "integrators/TimeStep.hpp"
#include "io/run/ProgressReporter.hpp"
#include "io/run/RunSummary.hpp"
#include "io/scene/Format.hpp"
#include "io/scene/ScenePath.hpp"
#include "io/vtk/FrameOutputs.hpp"
#include "numerics/SignalComparison.hpp"
#include "numerics/StableTimeStep.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/TimeLoop.hpp"
#include "particles/BoxFace.hpp"
#include "systems/LinearSecondOrderSystem.hpp"
#include "systems/SparseLoads.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

namespace mfwave::solid {

SceneSchema solidSchema() {
  using T = ValueType;
  SceneSchema s = SceneSchema::common();
  addSolidKeys(s);
  s.at("method.name").oneOf({"very_weak_sph"});
  CollocationKeyDefaults collocation;  // adds reproducing_kernel to method.name's choices
  collocation.supportNote = "2.5 in 2-D, 2.2 in 3-D (the widest supports whose interior rows do not grow)";
  collocation.supportAdvice = "from about 2.77 in 2-D and 2.5 in 3-D the interior rows grow";
  addCollocationKeys(s, collocation);
  s.add("method.variant", T::String).defaultsTo("\"galerkin\"").oneOf({"galerkin"})
      .describedAs("the very weak SPH variant: galerkin (the tent kernel integrated over the solid's cells)");
  s.add("method.cells", T::String).defaultsTo("\"cut\"").oneOf({"cut", "staircase"})
      .describedAs("cut: the integrals over the inside of each lattice cell the surface cuts; staircase: whole cells "
                   "whose centre is inside (the baseline)");
  s.add("method.cut_depth", T::Integer).withUnit("-").defaultsTo("4").between(0, 8)
      .describedAs("levels of subdivision of a cut cell (2^depth sub-cells per axis; the cut volume's error is of "
                   "order spacing / 2^depth)");
  s.add("method.small_cell_fraction", T::Number).withUnit("-").defaultsTo("0.25").between(0, 1, true, false)
      .describedAs("a node whose volume in the solid is below this fraction of its uncut volume is extended from its "
                   "neighbours (docs/theory/very-weak-sph.md, Cut cells)");
  s.add("probe[].direction", T::NumberArray).withUnit("-").defaultsToNote("the axis of component")
      .describedAs("record the component along this vector (normalised; e.g. a surface's inward normal) in place of "
                   "component's axis");
  s.add("probe_line", T::TableArray)
      .describedAs("receiver lines: count probes evenly from `from` to `to`, named <name>_000, <name>_001, ... (written "
                   "with the other probes, drawn as a record section)");
  s.add("probe_line[].name", T::String).required().describedAs("the line's name, the prefix of its probes' names");
  s.add("probe_line[].from", T::NumberArray).withUnit("m").required().describedAs("the first receiver");
  s.add("probe_line[].to", T::NumberArray).withUnit("m").required().describedAs("the last receiver");
  s.add("probe_line[].count", T::Integer).withUnit("-").required().between(2, 100000).describedAs("receivers on the line");
  s.add("probe_line[].quantity", T::String).defaultsTo("\"velocity\"").oneOf({"displacement", "velocity"})
      .describedAs("recorded field");
  s.add("probe_line[].direction", T::NumberArray).withUnit("-").required()
      .describedAs("every receiver records the component along this vector (normalised)");
  s.add("probe_grid", T::TableArray)
      .describedAs("receiver grids: counts[a] receivers evenly along each axis from lower to upper, named "
                   "<name>_<i>_<j>(_<k>); points outside the solid are left out");
  s.add("probe_grid[].name", T::String).required().describedAs("the grid's name, the prefix of its probes' names");
  s.add("probe_grid[].lower", T::NumberArray).withUnit("m").required().describedAs("the grid's lower corner");
  s.add("probe_grid[].upper", T::NumberArray).withUnit("m").required().describedAs("the grid's upper corner");
  s.add("probe_grid[].counts", T::NumberArray).withUnit("-").required()
      .describedAs("receivers along each axis (whole numbers >= 1; 1 puts them at lower)");
  s.add("probe_grid[].quantity", T::String).defaultsTo("\"velocity\"").oneOf({"displacement", "velocity"})
      .describedAs("recorded field");
  s.add("probe_grid[].direction", T::NumberArray).withUnit("-").required()
      .describedAs("every receiver records the component along this vector (normalised)");
  s.add("surface_boundary", T::TableArray)
      .describedAs("named surfaces of the solid held fixed (u = 0); the others are free (the box's faces take [[boundary]])");
  s.add("surface_boundary[].surface", T::String).required().describedAs("'<shape>.<surface>', e.g. 'inclusion.surface'");
  s.add("surface_boundary[].type", T::String).required().oneOf({"fixed"}).describedAs("fixed: zero displacement");
  s.add("study", T::Table).describedAs("the cases of the solid study");
  s.add("study.spacings", T::NumberArray).withUnit("m").defaultsToNote("geometry.spacing")
      .describedAs("lattice spacings, one case each (each must divide the box)");
  s.addChoice("method.name", "updated_lagrangian_sph");  // its small-amplitude defaults; no [method] keys here
  s.addChoice("method.name", "total_lagrangian_sph");    // its defaults
  s.add("study.methods", T::StringArray).defaultsToNote("[method.name]")
      .oneOf({"very_weak_sph", "reproducing_kernel", "updated_lagrangian_sph", "total_lagrangian_sph"})
      .describedAs("the methods run at each spacing, each scored the same way; [method] keys apply to method.name's "
                   "cases, the others run with their defaults");
  s.add("study.compare_staircase", T::Boolean).defaultsTo("true")
      .describedAs("run the staircase baseline beside the cut cells at every spacing");
  s.add("study.reference", T::String).defaultsTo("\"none\"").oneOf({"none", "lamb_strip"})
      .describedAs("exact reference: lamb_strip (2-D: a half-plane of any inclination loaded by a pressure on a "
                   "strip of its plane, LambStripLoad in its own coordinates)");
  s.add("study.error_window", T::Number).withUnit("s").defaultsToNote("integrator.end_time").positive()
      .describedAs("errors over 0 <= t <= error_window");
  return s;
}

namespace {

// A direction the scene gives (a probe's, a receiver line's or grid's), normalised.
template <int D>
Vec<D> readDirection(SceneReader& reader, const std::string& key) {
  const Vec<D> d = scene::vectorOf<D>(reader.numbers(key, D));
  if (!(d.norm() > 0)) reader.fail(key, "must not be the zero vector");
  return d.normalized();
}

// The [[shape]] entry of a name, or -1.
long shapeIndex(SceneReader& reader, const std::string& name) {
  for (std::size_t i = 0; i < reader.count("shape"); ++i)
    if (reader.string(scene::childPath(scene::indexPath("shape", i), "name")) == name) return static_cast<long>(i);
  return -1;
}

// Refuses at `key` a surface name that is not '<shape>.<surface>' of a [[shape]] (or of the box,
// where `boxToo`).
void checkSurfaceName(SceneReader& reader, const std::string& key, const std::string& surface, bool boxToo) {
  const std::size_t dot = surface.find('.');
  const std::string shape = surface.substr(0, dot);
  if (dot == std::string::npos || ((!boxToo || shape != "box") && shapeIndex(reader, shape) < 0))
    reader.fail(key, "'" + surface + "' is not '<shape>.<surface>' of a [[shape]] " +
                         (boxToo ? "(or box)" : "(the box's faces take [[boundary]])"));
}

}  // namespace

std::vector<Real> lambHalfPlaneSeries(const HalfPlaneLamb& lamb, const Material& material, const std::vector<Real>& x,
                                      const std::vector<Real>& times, bool velocity) {
  const LambStripLoad exact(material.lambda(), material.mu(), material.density(), lamb.halfWidth, lamb.times, lamb.values,
                            lamb.pressure);
  Real offset = 0, depth = 0;
  for (std::size_t a = 0; a < 2; ++a) {
    offset += (x[a] - lamb.centre[a]) * lamb.tangent[a];
    depth -= (x[a] - lamb.centre[a]) * lamb.normal[a];
  }
  // On the surface to round-off is on it: the interior formula at a depth of 1e-16 would see the
  // Rayleigh pole through a peak far narrower than its quadrature (LambStripLoad.hpp, Limits).
  if (depth < 1e-9 * std::max<Real>(1, std::abs(offset))) depth = 0;
  std::vector<Real> out;
  for (const Real t : times) out.push_back(velocity ? exact.velocity(offset, depth, t) : exact.displacement(offset, depth, t));
  return out;
}

template <int D>
bool SolidPlan<D>::fixedAt(const Vec<D>& x) const {
  if (fixedSurfaces.empty()) return false;
  return std::find(fixedSurfaces.begin(), fixedSurfaces.end(), solid.solid->surfaceName(x)) != fixedSurfaces.end();
}

template <int D>
void writeAndScoreProbes(const SolidPlan<D>& plan, const TimeSeries& recorded, const std::string& folder,
                         SolidCaseResult& result) {
  if (plan.probes.empty()) return;
  std::vector<std::string> columns;
  std::vector<std::vector<Real>> values, exact;
  for (std::size_t i = 0; i < plan.probes.size(); ++i) {
    columns.push_back(plan.probes[i].name);
    values.push_back(recorded.column(i));
    if (!plan.lamb) continue;
    columns.push_back(plan.probes[i].name + "_exact");
    const Real sign = plan.probes[i].direction.dot(-scene::vectorOf<D>(plan.lamb->normal)) > 0 ? 1.0 : -1.0;
    std::vector<Real> e = lambHalfPlaneSeries(*plan.lamb, plan.solid.materials[0],
                                              std::vector<Real>(plan.probes[i].position.data(), plan.probes[i].position.data() + D),
                                              recorded.times(), plan.probes[i].velocity);
    for (Real& x : e) x *= sign;
    const SignalErrors errors = compareSignals(recorded.times(), values.back(), e, plan.errorWindow);
    result.relativeL2.push_back(errors.relativeL2);
    result.peakError.push_back(errors.peakError);
    result.arrivalError.push_back(errors.arrivalError);
    exact.push_back(std::move(e));
  }
  TimeSeries table("t [s]", columns);
  for (std::size_t k = 0; k < recorded.rows(); ++k) {
    std::vector<Real> row;
    for (std::size_t i = 0; i < plan.probes.size(); ++i) {
      row.push_back(values[i][k]);
      if (plan.lamb) row.push_back(exact[i][k]);
    }
    table.append(recorded.times()[k], row);
  }
  table.writeCsv(folder + "/" + result.name + "-probes.csv");
  result.files.push_back(result.name + "-probes.csv");
}

template <int D>
SolidPlan<D> readSolidPlan(SceneReader& reader, const Scene& scene) {
  SolidPlan<D> plan;
  plan.scene = scene;
  if (scene.info.dimension != D || D < 2)
    reader.fail("scene.dimension", "the solid study runs 2-D and 3-D scenes");
  plan.methods = reader.has("study.methods") ? reader.strings("study.methods") : std::vector<std::string>{scene.method.name};
  if (plan.methods.empty()) reader.fail("study.methods", "names no method");
  for (std::size_t i = 0; i < plan.methods.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (plan.methods[i] == plan.methods[j]) reader.fail("study.methods", "names " + plan.methods[i] + " twice");
  for (const std::string& name : plan.methods)
    for (const UnsupportedFeature& f : unsupportedFeatures(scene, methodNamed(name))) {
      // the UL-SPH runs leapfrog at its own step, whatever the scene's integrator (the summary says so)
      if (name == "updated_lagrangian_sph" && f.key == "integrator.name") continue;
      reader.fail(f.key, f.message());
    }
  if (scene.integrator.kind != IntegratorKind::CentralDifference)
    reader.fail("integrator.name", "the solid study runs central_difference (its lumped mass makes it explicit)");
  plan.solid = readSceneSolid<D>(reader, scene);
  // fixed named surfaces: '<shape>.<surface>' of a [[shape]] (the box's faces take [[boundary]])
  for (std::size_t i = 0; i < reader.count("surface_boundary"); ++i) {
    const std::string key = scene::childPath(scene::indexPath("surface_boundary", i), "surface");
    const std::string surface = reader.string(key);
    checkSurfaceName(reader, key, surface, false);
    (void)reader.string(scene::childPath(scene::indexPath("surface_boundary", i), "type"));  // fixed
    plan.fixedSurfaces.push_back(surface);
  }
  const SolidFeatures asked{!plan.solid.regions.empty(), !plan.solid.cracks.empty(), !plan.fixedSurfaces.empty()};
  for (const std::string& name : plan.methods)
    for (const UnsupportedFeature& f : unsupportedSolidFeatures(methodNamed(name), asked)) reader.fail(f.key, f.message());
  if (plan.runs("reproducing_kernel")) {
    if (scene.method.name == "reproducing_kernel") {
      plan.collocation = readCollocationSpec(reader, scene.method.name, kProgram);
    } else {
      plan.collocation.supportRatio = D == 2 ? 2.5 : 2.2;  // the widest supports whose interior rows do not grow
    }
    const CollocationGrowingModes growth =
        rkGrowingModes(D, plan.collocation.order, plan.collocation.supportRatio, plan.solid.materials[0]);
    if (growth.growing()) reader.fail("method.support_ratio", growth.what + "; " + growth.advice);
  }
  const GeometrySpec& g = scene.geometry;

  for (std::size_t i = 0; i < scene.boundaries.size(); ++i) {
    const BoundaryType type = scene.boundaries[i].type;
    if (type != BoundaryType::Free && type != BoundaryType::Transmitting)
      reader.fail("boundary[" + std::to_string(i) + "].type",
                  "the solid study takes free and transmitting box faces (the solid's own surfaces are free; load them "
                  "with surface_traction)");
  }
  for (std::size_t i = 0; i < scene.loads.size(); ++i) {
    const LoadSpec& load = scene.loads[i];
    const std::string key = "load[" + std::to_string(i) + "]";
    if (load.type == LoadType::SurfacePatch || load.type == LoadType::BodyForce)
      reader.fail(key + ".type", "the solid study takes point_force, moment_tensor and surface_traction loads (a "
                                 "surface_patch is a box face's: use surface_traction on '<shape>.<surface>')");
    if (load.type != LoadType::SurfaceTraction) continue;
    checkSurfaceName(reader, key + ".surface", load.surface, true);
    if (std::find(plan.fixedSurfaces.begin(), plan.fixedSurfaces.end(), load.surface) != plan.fixedSurfaces.end())
      reader.fail(key + ".surface", "'" + load.surface + "' is held fixed by a [[surface_boundary]]: a load there does nothing");
  }

  for (std::size_t i = 0; i < scene.probes.size(); ++i) {
    const ProbeSpec& p = scene.probes[i];
    const std::string key = scene::indexPath("probe", i);
    if (!p.position) reader.fail(scene::childPath(key, "particle"), "the solid study places probes by position");
    SolidProbe<D> probe;
    probe.name = p.name;
    probe.position = scene::vectorOf<D>(*p.position);
    probe.velocity = p.quantity == ProbeQuantity::Velocity;
    if (plan.solid.solid->signedDistance(probe.position) > 1e-9 * g.spacing)
      reader.fail(scene::childPath(key, "position"), scene::formatPoint(*p.position) + " lies outside the solid");
    if (reader.has(scene::childPath(key, "direction"))) {
      probe.direction = readDirection<D>(reader, scene::childPath(key, "direction"));
    } else {
      probe.direction = Vec<D>::Unit(p.component);
    }
    plan.probes.push_back(probe);
  }

  for (std::size_t l = 0; l < reader.count("probe_line"); ++l) {
    const std::string entry = scene::indexPath("probe_line", l);
    const auto key = [&](const char* k) { return scene::childPath(entry, k); };
    const std::string name = reader.string(key("name"));
    const Vec<D> from = scene::vectorOf<D>(reader.numbers(key("from"), D)), to = scene::vectorOf<D>(reader.numbers(key("to"), D));
    const auto count = static_cast<int>(reader.integer(key("count")));
    const Vec<D> direction = readDirection<D>(reader, key("direction"));
    const bool velocity = reader.string(key("quantity")) == "velocity";
    for (int k = 0; k < count; ++k) {
      SolidProbe<D> probe;
      std::ostringstream label;
      label << name << '_' << std::setw(3) << std::setfill('0') << k;
      probe.name = label.str();
      probe.position = from + (to - from) * (static_cast<Real>(k) / (count - 1));
      probe.direction = direction;
      probe.velocity = velocity;
      if (plan.solid.solid->signedDistance(probe.position) > 1e-9 * g.spacing)
        reader.fail(key("to"), "receiver " + probe.name + " at " +
                                   scene::formatPoint(std::vector<Real>(probe.position.data(), probe.position.data() + D)) +
                                   " lies outside the solid");
      for (const SolidProbe<D>& other : plan.probes)
        if (other.name == probe.name) reader.fail(key("name"), "probe " + probe.name + " exists already");
      plan.probes.push_back(probe);
    }
  }
  for (std::size_t l = 0; l < reader.count("probe_grid"); ++l) {
    const std::string entry = scene::indexPath("probe_grid", l);
    const auto key = [&](const char* k) { return scene::childPath(entry, k); };
    const std::string name = reader.string(key("name"));
    const Vec<D> lower = scene::vectorOf<D>(reader.numbers(key("lower"), D)), upper = scene::vectorOf<D>(reader.numbers(key("upper"), D));
    const std::vector<int> counts = reader.wholeNumbers(key("counts"));
    if (counts.size() != static_cast<std::size_t>(D)) reader.fail(key("counts"), "needs one count per axis");
    Index total = 1;
    for (const int c : counts) {
      if (c < 1) reader.fail(key("counts"), "every count must be at least 1");
      total *= c;
    }
    if (total > 100000) reader.fail(key("counts"), "more than 100000 receivers in one grid");
    const Vec<D> direction = readDirection<D>(reader, key("direction"));
    const bool velocity = reader.string(key("quantity")) == "velocity";
    Index kept = 0;
    for (Index p = 0; p < total; ++p) {
      Index rest = p;
      SolidProbe<D> probe;
      std::ostringstream label;
      label << name;
      for (int a = 0; a < D; ++a) {
        const int c = counts[static_cast<std::size_t>(a)];
        const Index i = rest % c;
        rest /= c;
        probe.position[a] = c == 1 ? lower[a] : lower[a] + (upper[a] - lower[a]) * static_cast<Real>(i) / (c - 1);
        label << '_' << i;
      }
      if (plan.solid.solid->signedDistance(probe.position) > 1e-9 * g.spacing) continue;  // outside the solid
      probe.name = label.str();
      probe.direction = direction;
      probe.velocity = velocity;
      plan.probes.push_back(probe);
      ++kept;
    }
    if (kept == 0) reader.fail(key("lower"), "no receiver of grid '" + name + "' lies in the solid");
  }
  plan.spacings = reader.has("study.spacings") ? reader.numbers("study.spacings") : std::vector<Real>{g.spacing};
  if (plan.spacings.empty()) reader.fail("study.spacings", "names no spacing");
  for (const Real dx : plan.spacings) {
    try {
      (void)g.withLattice(g.lower, g.upper, dx);
    } catch (const InputError& e) {
      reader.fail("study.spacings", e.problem());
    }
  }
  // the very weak SPH's keys (read whether or not it runs: a scene may name them for a later run)
  const CutCells cells = reader.string("method.cells") == "staircase" ? CutCells::Staircase : CutCells::Cut;
  const bool staircaseToo = reader.boolean("study.compare_staircase") && cells == CutCells::Cut;
  plan.depth = static_cast<int>(reader.integer("method.cut_depth"));
  plan.smallCellFraction = reader.number("method.small_cell_fraction");
  (void)reader.string("method.variant");
  if (plan.runs("very_weak_sph")) {
    plan.cells.push_back(cells);
    if (staircaseToo) plan.cells.push_back(CutCells::Staircase);
  }
  plan.errorWindow = reader.has("study.error_window") ? reader.number("study.error_window") : scene.integrator.endTime;

  if (reader.string("study.reference") == "lamb_strip") {
    const auto fail = [&reader](const std::string& k, const std::string& why) {
      reader.fail(k, "the lamb_strip reference needs " + why);
    };
    if (D != 2) fail("study.reference", "a 2-D scene");
    if (scene.loads.size() != 1 || scene.loads[0].type != LoadType::SurfaceTraction || !scene.loads[0].traction.empty())
      fail("load", "exactly one surface_traction load given by its pressure");
    if (!plan.solid.regions.empty()) fail("region", "one material (no [[region]])");
    const LoadSpec& load = scene.loads[0];
    const std::string shape = load.surface.substr(0, load.surface.find('.'));
    const long k = shapeIndex(reader, shape);
    const std::string entry = scene::indexPath("shape", static_cast<std::size_t>(std::max(k, 0L)));
    if (k < 0 || reader.string(scene::childPath(entry, "type")) != "half_space" || load.surface != shape + ".plane")
      fail("load[0].surface", "the plane of a half_space shape ('<name>.plane')");
    HalfPlaneLamb lamb;
    const Vec<D> normal = scene::vectorOf<D>(reader.numbers(scene::childPath(entry, "normal"), D)).normalized();
    const Vec<D> point = scene::vectorOf<D>(reader.numbers(scene::childPath(entry, "point"), D));
    const Vec<D> centre = scene::vectorOf<D>(load.centre);
    if (std::abs((centre - point).dot(normal)) > 1e-9) fail("load[0].centre", "the load's centre on the half-plane's surface");
    lamb.centre = load.centre;
    lamb.normal = {normal[0], normal[1]};
    lamb.tangent = {-normal[1], normal[0]};
    lamb.halfWidth = load.radius;
    lamb.pressure = load.pressure;
    if (!load.timeFunction.piecewiseLinear(lamb.times, lamb.values) || lamb.values.front() != 0)
      fail("load[0].time_function", "a piecewise-linear history starting from 0");
    for (std::size_t i = 0; i < plan.probes.size(); ++i)
      if (std::abs(std::abs(plan.probes[i].direction.dot(normal)) - 1) > 1e-9)
        fail(scene::childPath(scene::indexPath("probe", i), "direction"),
             "probes recording along the half-plane's normal (the reference is that component)");
    plan.lamb = lamb;
  }
  return plan;
}

template <int D>
SolidCaseResult runSolidCase(const SolidPlan<D>& plan, Real spacing, CutCells cells, const std::string& folder,
                             bool frames, bool progress) {
  const Scene& scene = plan.scene;
  const Stopwatch setup;
  const bool cut = cells == CutCells::Cut;
  SolidCaseResult result = startCase(cut ? "cut" : "staircase", "very_weak_sph", cut ? "cut" : "staircase", spacing);

  // the method on the solid: its surfaces are the expression's (the box's faces are the lattice's own)
  const SceneSolid<D>& solid = plan.solid;
  CutCellDomain<D> domain;
  domain.distance = [surfaces = solid.unbounded](const Vec<D>& x) { return surfaces->signedDistance(x); };
  domain.materials = solid.materials;
  domain.materialAt = [&solid](const Vec<D>& x) { return solid.materialAt(x); };
  if (!solid.regions.empty()) domain.interfaceDistance = [&solid](const Vec<D>& x) { return solid.interfaceDistance(x); };
  CutCellSettings<D> settings;
  settings.lower = scene::vectorOf<D>(scene.geometry.lower);
  settings.upper = scene::vectorOf<D>(scene.geometry.upper);
  settings.spacing = spacing;
  settings.cells = cells;
  settings.depth = plan.depth;
  settings.smallCellFraction = plan.smallCellFraction;
  settings.transmittingFaces = facesWith(scene.boundaries, BoundaryType::Transmitting);
  const CutCellGalerkin<D> method(domain, settings);
  result.unknowns = method.unknownNodes();
  result.extended = method.extendedNodes();
  result.cutCells = method.cutCells();
  result.volume = method.volume();
  result.smallestKept = method.smallestKeptFraction();

  // loads, each a fixed vector scaled by its time function
  std::vector<SparseLoad> loads;
  for (std::size_t i = 0; i < scene.loads.size(); ++i) {
    const LoadSpec& load = scene.loads[i];
    if (load.type == LoadType::PointForce) {
      loads.push_back(nonzeroLoad(method.pointForce(scene::vectorOf<D>(load.position),
                                                    load.amplitude * scene::vectorOf<D>(load.direction)),
                                  &load.timeFunction));
    } else if (load.type == LoadType::MomentTensor) {
      Mat<D> m;
      if constexpr (D == 2) {
        m << load.moment[0], load.moment[2], load.moment[2], load.moment[1];
      } else {
        m << load.moment[0], load.moment[3], load.moment[4], load.moment[3], load.moment[1], load.moment[5], load.moment[4],
            load.moment[5], load.moment[2];
      }
      loads.push_back(nonzeroLoad(method.momentTensor(scene::vectorOf<D>(load.position), m), &load.timeFunction));
    } else {
      const Vec<D> centre = scene::vectorOf<D>(load.centre);
      const Real radius = load.radius;
      const std::string surface = load.surface;
      const auto on = [&, centre, radius](const Vec<D>& x) {
        return (x - centre).norm() <= radius && solid.solid->surfaceName(x) == surface;
      };
      const bool pressure = load.traction.empty();
      const Vec<D> vector = pressure ? Vec<D>::Zero() : scene::vectorOf<D>(load.traction);
      const Real p = load.pressure;
      Vector f = method.surfaceTraction(on, [pressure, vector, p](const Vec<D>&, const Vec<D>& n) -> Vec<D> {
        return pressure ? Vec<D>(-p * n) : vector;
      });
      if (!(f.cwiseAbs().maxCoeff() > 0))
        throw InputError("load[" + std::to_string(i) + "].surface",
                         "no point of surface '" + surface + "' lies within " + scene::formatNumber(radius) + " of " +
                             scene::formatPoint(load.centre) + " (the solid's surfaces are named '<shape>.<surface>')");
      loads.push_back(nonzeroLoad(f, &load.timeFunction));
    }
  }
  const Index n = method.size();
  LinearSecondOrderSystem system(method.mass(), method.damping(), method.stiffness(), [&loads, n](Real t, Vector& f) {
    f.setZero(n);
    addSparseLoads(loads, t, f.data());
  });

  // the step: cfl of the power iteration's stable step, or the scene's fixed step
  const StableTimeStep stable = centralDifferenceStableStep(system, 1e-6, 20000);
  result.stableStep = stable.usable();
  const TimeStepChoice step = chooseTimeStep(scene.integrator.stepRule(), result.stableStep);
  result.dt = step.dt;

  // initial displacements and velocities by region
  Vector u0 = Vector::Zero(n), v0 = Vector::Zero(n);
  for (Index a = 0; a < method.unknownNodes(); ++a) {
    const int region = solid.regionAt(method.unknownPositions()[static_cast<std::size_t>(a)]);
    if (region < 0) continue;
    const auto r = static_cast<std::size_t>(region);
    if (!solid.initialVelocity[r].empty()) v0.template segment<D>(D * a) = scene::vectorOf<D>(solid.initialVelocity[r]);
    if (!solid.initialDisplacement[r].empty()) u0.template segment<D>(D * a) = scene::vectorOf<D>(solid.initialDisplacement[r]);
  }
  std::unique_ptr<SecondOrderIntegrator> integrator = makeSecondOrderIntegrator(scene.integrator.name, scene.integrator.options);
  integrator->initialise(system, 0, u0, v0, step.dt);

  // probes: the field's component along each direction, interpolated at the position
  std::vector<std::vector<std::pair<Index, Real>>> rows;
  std::vector<bool> velocity;
  for (const SolidProbe<D>& p : plan.probes) {
    std::map<Index, Real> row;
    for (int c = 0; c < D; ++c)
      if (p.direction[c] != 0)
        for (const auto& [dof, w] : method.interpolation(p.position, c)) row[dof] += p.direction[c] * w;
    rows.emplace_back(row.begin(), row.end());
    velocity.push_back(p.velocity);
  }
  SampledProbes probes(probeNames(plan), rowSampler(std::move(rows), std::move(velocity)));
  StabilityMonitor monitor(scene.stability.options(D, loadsQuietAfter(scene)));
  ProgressReporter reporter(scene.integrator.endTime, method.unknownNodes(), progress);
  TimeLoop loop;
  loop.add(monitor);
  loop.add(reporter);
  if (!plan.probes.empty()) loop.add(probes, scene.output.probeEvery);
  ParticleSet<D> nodes;
  for (Index a = 0; a < method.unknownNodes(); ++a)
    nodes.add(method.unknownPositions()[static_cast<std::size_t>(a)], method.mass().coeff(D * a, D * a));
  ParticleFrames<D> particleFrames(nodes, folder, result.name, frameSettings<D>(scene.output, frames));
  particleFrames.attachTo(loop, scene.output.every);
  result.setupSeconds = setup.seconds();
  recordRun(result, loop.run(*integrator, scene.integrator.endTime));
  const FrameOutputReport report = particleFrames.report();
  for (const std::string& f : report.files) result.files.push_back(f);

  writeAndScoreProbes(plan, probes.series(), folder, result);
  return result;
}

template struct SolidPlan<2>;
template struct SolidPlan<3>;
template SolidPlan<2> readSolidPlan<2>(SceneReader&, const Scene&);
template SolidPlan<3> readSolidPlan<3>(SceneReader&, const Scene&);
template SolidCaseResult runSolidCase<2>(const SolidPlan<2>&, Real, CutCells, const std::string&, bool, bool);
template void writeAndScoreProbes<2>(const SolidPlan<2>&, const TimeSeries&, const std::string&, SolidCaseResult&);
template void writeAndScoreProbes<3>(const SolidPlan<3>&, const TimeSeries&, const std::string&, SolidCaseResult&);
template SolidCaseResult runSolidCase<3>(const SolidPlan<3>&, Real, CutCells, const std::string&, bool, bool);

}  // namespace mfwave::solid
