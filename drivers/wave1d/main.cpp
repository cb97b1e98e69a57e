// wave1d: standing waves in a fixed-fixed bar, u_tt = c^2 u_xx, discretised on a line of
// particles by the reference finite-difference operator and advanced by each integrator.
//
// What it shows: the whole pipeline (lattice -> neighbours -> operator -> integrator ->
// observers) against an exact solution, the convergence order in dx at a fixed CFL number, and
// the cost of each integrator for a given error. Results: docs/studies/wave1d.md.

#include "analytic/StandingWave.hpp"
#include "core/AtomicFile.hpp"
#include "core/Error.hpp"
#include "integrators/IntegratorFactory.hpp"
#include "methods/finite_difference/FiniteDifferenceWaveOperator.hpp"
#include "neighbours/NeighbourList.hpp"
#include "observers/EnergyObserver.hpp"
#include "observers/ProbeRecorder.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/TimeLoop.hpp"
#include "particles/BoxFace.hpp"
#include "particles/Lattice.hpp"

#include <CLI/CLI.hpp>

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using namespace mfwave;

namespace {

struct Study {
  Real length = 1;
  Real density = 1;
  Real modulus = 1;
  int mode = 1;
  Real endTime = 2.3;  // not a multiple of the half period, so u(T) is not zero anywhere
  Real cfl = 0.5;
  std::vector<int> cells{32, 64, 128, 256, 512, 1024, 2048};
  std::vector<std::string> integrators{"central_difference", "leapfrog", "newmark", "arkode"};
  std::string out = "out/wave1d";
};

struct CaseResult {
  std::string integrator;
  int cells;
  Real dx, dt;
  long steps;
  Real error;
  Real energyDrift;
  double wallSeconds;
};

CaseResult runCase(const Study& study, const std::string& integratorName, int cellCount, bool writeSeries) {
  const Real dx = study.length / cellCount;
  const Real waveSpeed = std::sqrt(study.modulus / study.density);
  const StandingWave exact(study.mode, study.length, waveSpeed);

  // particles + neighbours
  const ParticleSet<1> line = makeLine(0, study.length, dx);
  const NeighbourList neighbours = buildNeighbourList(CellList<1>(line, 1.5 * dx));
  // discretisation
  FiniteDifferenceWaveOptions fd;
  fd.spacing = dx;
  fd.density = study.density;
  fd.modulus = study.modulus;
  fd.fixedFaces = faceBit(BoxFace::MinusX) | faceBit(BoxFace::PlusX);
  LinearSecondOrderSystem system = assembleFiniteDifferenceWave(line, neighbours, fd);

  Vector u0(line.size()), v0(line.size());
  for (Index i = 0; i < line.size(); ++i) {
    u0[i] = exact.displacement(line.position(i)[0], 0);
    v0[i] = exact.velocity(line.position(i)[0], 0);
  }
  // integrator: the largest step below cfl * dx / c that lands on the end time
  const long steps = static_cast<long>(std::ceil(study.endTime * waveSpeed / (study.cfl * dx) - 1e-9));
  const Real dt = study.endTime / static_cast<Real>(steps);
  IntegratorOptions integratorOptions;
  auto integrator = makeSecondOrderIntegrator(integratorName, integratorOptions);
  integrator->initialise(system, 0, u0, v0, dt);

  // observers
  StabilityMonitor monitor;
  EnergyObserver energy(EnergyObserver::ofLinearSystem(system));
  const Index quarter = line.size() / 4;
  ProbeRecorder probes({{"quarter", quarter, 0, ProbeQuantity::Displacement}}, 1, "s", "m");
  TimeLoop loop;
  loop.add(monitor);
  loop.add(energy);
  if (writeSeries) loop.add(probes);
  const RunStatistics stats = loop.run(*integrator, study.endTime);

  // error at the end time, relative to the L2 norm of the mode shape (u(T) itself may be small)
  const Vector& u = integrator->state().displacement;
  Real errorSquared = 0, normSquared = 0;
  for (Index i = 0; i < line.size(); ++i) {
    const Real x = line.position(i)[0];
    errorSquared += std::pow(u[i] - exact.displacement(x, stats.endTime), 2);
    normSquared += std::pow(std::sin(exact.wavenumber() * x), 2);
  }
  if (writeSeries) {
    const std::string stem = study.out + "/" + integratorName + "-" + std::to_string(cellCount);
    probes.series().writeCsv(stem + "-probe.csv");
    energy.series().writeCsv(stem + "-energy.csv");
  }
  return {integratorName, cellCount, dx, dt, stats.steps, std::sqrt(errorSquared / normSquared),
          energy.maxRelativeDrift(), stats.wallSeconds};
}

}  // namespace

int main(int argc, char** argv) {
  Study study;
  CLI::App app{"wave1d: standing wave in a fixed-fixed bar; convergence and cost of each integrator"};
  app.add_option("--out", study.out, "output folder")->capture_default_str();
  app.add_option("--cells", study.cells, "resolutions (cells along the bar)")->capture_default_str();
  app.add_option("--integrators", study.integrators,
                 "integrators: central_difference leapfrog newmark arkode")->capture_default_str();
  app.add_option("--cfl", study.cfl, "c dt / dx")->capture_default_str();
  app.add_option("--end-time", study.endTime, "simulated time")->capture_default_str();
  app.add_option("--mode", study.mode, "standing-wave mode number n")->capture_default_str();
  bool quiet = false;
  app.add_flag("--quiet", quiet, "print only the summary table");
  app.set_version_flag("--version", "wave1d (mfwave 0.1.0)");
  CLI11_PARSE(app, argc, argv);

  try {
    if (!(study.cfl > 0)) throw InputError("cfl", "must be positive");
    if (!(study.endTime > 0)) throw InputError("end_time", "must be positive");
    if (study.cells.empty()) throw InputError("cells", "give at least one resolution");
    for (int c : study.cells)
      if (c < 4 * study.mode) throw InputError("cells", "each resolution needs at least 4 cells per half wave");
    std::filesystem::create_directories(study.out);

    std::vector<CaseResult> results;
    for (const auto& name : study.integrators)
      for (std::size_t r = 0; r < study.cells.size(); ++r) {
        results.push_back(runCase(study, name, study.cells[r], r + 1 == study.cells.size()));
        if (!quiet) std::cerr << "  done " << name << " with " << study.cells[r] << " cells\n";
      }

    AtomicFile table(study.out + "/convergence.csv");
    table.stream() << "integrator,cells,dx [m],dt [s],steps,relative_l2_error,observed_order,"
                      "energy_drift,wall_time [s],particle_steps_per_s\n";
    std::cout << std::left << std::setw(20) << "integrator" << std::right << std::setw(7) << "cells" << std::setw(10)
              << "dt" << std::setw(13) << "L2 error" << std::setw(8) << "order" << std::setw(12) << "energy" << std::setw(11)
              << "wall [s]" << std::setw(14) << "part-steps/s" << '\n';
    for (std::size_t i = 0; i < results.size(); ++i) {
      const CaseResult& r = results[i];
      const bool hasCoarser = i > 0 && results[i - 1].integrator == r.integrator;
      const Real order = hasCoarser ? std::log(results[i - 1].error / r.error) / std::log(results[i - 1].dx / r.dx)
                                    : std::nan("");
      const double rate = static_cast<double>(r.cells + 1) * static_cast<double>(r.steps) / std::max(r.wallSeconds, 1e-9);
      table.stream() << r.integrator << ',' << r.cells << ',' << r.dx << ',' << r.dt << ',' << r.steps << ','
                     << r.error << ',' << order << ',' << r.energyDrift << ',' << r.wallSeconds << ',' << rate << '\n';
      std::cout << std::left << std::setw(20) << r.integrator << std::right << std::setw(7) << r.cells
                << std::setw(10) << std::setprecision(3) << r.dt << std::setw(13) << std::scientific
                << std::setprecision(3) << r.error << std::defaultfloat << std::setw(8) << std::setprecision(3)
                << order << std::setw(12) << std::scientific << std::setprecision(2) << r.energyDrift
                << std::defaultfloat << std::setw(11) << std::setprecision(3) << r.wallSeconds << std::setw(14)
                << std::scientific << std::setprecision(2) << rate << std::defaultfloat << '\n';
    }
    table.commit();
    std::cout << "wrote " << study.out << "/convergence.csv\n";
    return 0;
  } catch (const InstabilityError& e) {
    std::cerr << "wave1d: run stopped: " << e.what() << '\n';
    return 3;
  } catch (const Error& e) {
    std::cerr << "wave1d: error: " << e.what() << '\n';
    return 2;
  }
}
