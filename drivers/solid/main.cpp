// solid: runs a scene whose solid is made of shapes (a half-plane of any inclination, layers, a
// cavity, a CAD surface, cracks) by the Galerkin very weak SPH on cut lattice cells (and the staircase
// of whole cells beside it), by RK collocation on lattice and surface nodes, and by the updated- and
// total-Lagrangian SPH on a body-fitted fill (study.methods), at each of study.spacings; loads
// anywhere (point forces, moment tensors, tractions on a named surface), fixed named surfaces,
// probes anywhere along any direction, and the errors
// against the exact 2-D Lamb response where the scene is a loaded half-plane (study.reference =
// "lamb_strip"). Results: docs/studies/geometry.md. Plot: /usr/bin/python3 analysis/plot_solid.py OUT.
//
//   solid --scene data/scenes/lamb2d_inclined.toml [--set key=value ...] [--out DIR]

#include "catalogue/MethodCatalogue.hpp"
#include "catalogue/SceneSupport.hpp"
#include "core/AtomicFile.hpp"
#include "core/Error.hpp"
#include "io/run/DriverCommandLine.hpp"
#include "io/run/RunDriver.hpp"
#include "io/run/RunSummary.hpp"
#include "io/run/SceneDriver.hpp"
#include "io/scene/Format.hpp"
#include "io/scene/LoadScene.hpp"
#include "io/scene/Scene.hpp"
#include "studies/solid/SolidStudy.hpp"

#include <iomanip>
#include <iostream>

using namespace mfwave;
using namespace mfwave::solid;

namespace {

template <int D>
int run(SceneReader& reader, const Scene& scene, const DriverOptions& options) {
  const SolidPlan<D> plan = readSolidPlan<D>(reader, scene);
  reader.checkAllKeysRead();  // unknown keys: before any work
  const std::string folder = prepareOutputFolder(options, scene.output.folder, reader);
  RunSummary summary(kProgram, scene.info.name, scene.method.name, scene.integrator.name);

  std::vector<SolidCaseResult> results;
  bool first = true;
  for (const Real dx : plan.spacings) {
    for (const CutCells cells : plan.cells) {
      results.push_back(runSolidCase<D>(plan, dx, cells, folder, first, !options.quiet));
      first = false;
    }
    if (plan.runs("reproducing_kernel")) {
      results.push_back(runSolidCollocationCase<D>(plan, dx, folder, first, !options.quiet));
      first = false;
    }
    if (plan.runs("updated_lagrangian_sph"))
      results.push_back(runSolidSphCase<D>(plan, dx, folder, !options.quiet));
    if (plan.runs("total_lagrangian_sph"))
      results.push_back(runSolidTotalLagrangianCase<D>(plan, dx, folder, !options.quiet));
  }

  // cases.csv: one row per case, the errors of every probe
  {
    AtomicFile file(folder + "/cases.csv");
    std::ostream& out = file.stream();
    out << std::setprecision(10) << "case,method,cells,spacing [m],unknowns,extended,cut_cells,volume [m^" << D
        << "],smallest_kept_fraction,stable_step [s],dt [s],steps,setup [s],run [s],peak_memory [MiB]";
    for (const SolidProbe<D>& p : plan.probes)
      if (plan.lamb) out << ',' << p.name << "_relative_l2," << p.name << "_peak_error," << p.name << "_arrival_error [s]";
    out << '\n';
    for (const SolidCaseResult& r : results) {
      out << r.name << ',' << r.method << ',' << r.cells << ',' << r.spacing << ',' << r.unknowns << ',' << r.extended << ',' << r.cutCells
          << ',' << r.volume << ',' << r.smallestKept << ',' << r.stableStep << ',' << r.dt << ',' << r.steps << ','
          << r.setupSeconds << ',' << r.runSeconds << ',' << r.peakMiB;
      for (std::size_t i = 0; i < r.relativeL2.size(); ++i)
        out << ',' << r.relativeL2[i] << ',' << r.peakError[i] << ',' << r.arrivalError[i];
      out << '\n';
    }
    file.commit();
  }
  summary.files.add("cases.csv");
  // receivers.csv: where each probe reads and along what (the record section's distances)
  {
    AtomicFile file(folder + "/receivers.csv");
    std::ostream& out = file.stream();
    out << std::setprecision(12) << "name";
    for (int a = 0; a < D; ++a) out << ",x" << a << " [m]";
    for (int a = 0; a < D; ++a) out << ",direction_" << a;
    out << ",quantity\n";
    for (const SolidProbe<D>& p : plan.probes) {
      out << p.name;
      for (int a = 0; a < D; ++a) out << ',' << p.position[a];
      for (int a = 0; a < D; ++a) out << ',' << p.direction[a];
      out << ',' << (p.velocity ? "velocity" : "displacement") << '\n';
    }
    file.commit();
  }
  summary.files.add("receivers.csv");
  for (const SolidCaseResult& r : results) {
    summary.files.addAll(r.files);
    CaseRecord record;
    record.name = r.name;
    record.particles = r.unknowns;
    record.steps = r.steps;
    record.timeStep = r.dt;
    record.stableTimeStep = r.stableStep;
    record.simulatedTime = scene.integrator.endTime;
    record.setupSeconds = r.setupSeconds;
    record.loopSeconds = r.runSeconds;
    record.peakMemoryMiB = r.peakMiB;
    summary.addCase(record);
    for (std::size_t i = 0; i < r.relativeL2.size(); ++i)
      summary.figures.push_back({r.name + "_" + plan.probes[i].name + "_relative_l2", r.relativeL2[i]});
    summary.figures.push_back({r.name + "_extended_nodes", static_cast<Real>(r.extended)});
    summary.figures.push_back({r.name + "_stable_step", r.stableStep});
  }
  summary.particles = results.front().unknowns;
  summary.timeStep = results.front().dt;
  summary.simulatedTime = scene.integrator.endTime;
  for (const SolidCaseResult& r : results) {
    summary.steps += r.steps;
    summary.wallSeconds += r.setupSeconds + r.runSeconds;
  }
  summary.notes.add("particles and dt of the first case (" + results.front().name + "); steps and wall time summed over " +
                    std::to_string(results.size()) + " cases");
  if (!plan.lamb) summary.notes.add("no reference solution for this scene: no error reported");
  if (!plan.cells.empty())
    summary.notes.add("very_weak_sph: the Galerkin variant on cut lattice cells (depth " + std::to_string(plan.depth) +
                      ", small-cell fraction " + mfwave::scene::formatNumber(plan.smallCellFraction) + ")" +
                      (plan.cells.size() > 1 ? ", with the staircase baseline" : ""));
  if (plan.runs("reproducing_kernel")) {
    summary.notes.add("reproducing_kernel: RK collocation (" + plan.collocation.describe() +
                      ") on the lattice nodes at least half a spacing inside the solid and nodes on its surfaces with "
                      "traction rows (cases rk_<spacing>; cut_cells counts its surface nodes)");
    for (const std::string& note : standInNotes(scene, methodNamed("reproducing_kernel"))) summary.notes.add(note);
  }
  if (plan.runs("updated_lagrangian_sph")) {
    summary.notes.add("updated_lagrangian_sph: the SPH for solids on a body-fitted fill (cases ulsph_<spacing>; "
                      "cut_cells counts its surface particles), the Lamb study's small-amplitude choices (alpha = 1, "
                      "kernel-gradient correction), traction times " + mfwave::scene::formatNumber(kSmallAmplitude) +
                      " and probes over it; leapfrog at its own step (integrator.name = " + scene.integrator.name +
                      " and cfl not used)");
    for (const std::string& note : standInNotes(scene, methodNamed("updated_lagrangian_sph"))) summary.notes.add(note);
  }
  if (plan.runs("total_lagrangian_sph")) {
    summary.notes.add("total_lagrangian_sph: the total-Lagrangian SPH on the same fill (cases tlsph_<spacing>), its "
                      "defaults (h = 1.3 dx, hourglass factor 1), the same small amplitude, the scene's integrator");
    for (const std::string& note : standInNotes(scene, methodNamed("total_lagrangian_sph"))) summary.notes.add(note);
  }
  summary.conclude(folder, &std::cout);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const SceneSchema schema = solidSchema();
  DriverCommandLine cli(kProgram,
                        "solid: a scene's own solid (shapes, regions, cracks, sources, receivers) by the Galerkin very "
                        "weak SPH on cut lattice cells, RK collocation, and the updated- and total-Lagrangian SPH",
                        schema.describe());
  cli.setDefaultScene("lamb2d_inclined.toml");
  if (const auto exit = cli.parse(argc, argv)) return *exit;
  return runDriver(kProgram, [&]() -> int {
    SceneReader reader = loadDriverScene(cli.options(), schema);
    const Scene scene = readScene(reader);
    if (scene.info.dimension == 3) return run<3>(reader, scene, cli.options());
    return run<2>(reader, scene, cli.options());
  });
}
