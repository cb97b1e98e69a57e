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
// [--set method.viscosity_alpha=1] [--set method.viscosity_beta=0] [--set method.kernel_gradient_correction=true]
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
#include "studies/lamb3d/LambPlan.hpp"

#include "core/Error.hpp"
#include "core/Interruption.hpp"
#include "io/run/CaseTable.hpp"
#include "io/run/DriverCommandLine.hpp"
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
const char* kProgram = lambProgram(kDimension);


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
  const SceneSchema schema = lambSchema(kDimension);
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
    const Plan plan = readLambPlan<kDimension>(reader);
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
