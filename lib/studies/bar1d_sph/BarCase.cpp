#include "BarCase.hpp"

#include "analytic/SymmetricBarImpact.hpp"
#include "core/AtomicFile.hpp"
#include "core/Stopwatch.hpp"
#include "io/vtk/FrameOutputs.hpp"
#include "io/vtk/VtkFrameWriter.hpp"
#include "methods/updated_lagrangian_sph/UpdatedLagrangianSph.hpp"
#include "observers/TimeLoop.hpp"
#include "wiring/EnergyLedger.hpp"
#include "wiring/SolidStateAdapter.hpp"

#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>

namespace mfwave::bar1dsph {

std::string profileFileName(Real dx) {
  std::ostringstream name;
  name << "profile-" << dx << ".csv";
  return name.str();
}

namespace {

// Cell-centred particles x_i = -L + (i + 1/2) dx: no particle sits on the interface, and each bar
// holds exactly L / dx particles (dx is adjusted down to divide L).
ParticleSet<1> twoBars(Real halfLength, Real& dx) {
  const auto perBar = static_cast<Index>(std::ceil(halfLength / dx - 1e-9));
  dx = halfLength / static_cast<Real>(perBar);
  ParticleSet<1> particles;
  particles.reserve(2 * perBar);
  for (Index i = 0; i < 2 * perBar; ++i) particles.add(Vec1(-halfLength + (static_cast<Real>(i) + 0.5) * dx), dx);
  return particles;
}

// The right-going front: the largest x > 0 where sigma has reached half the plateau stress, with
// linear interpolation between the particles on either side of the crossing.
Real measuredFront(const std::vector<Real>& x, const std::vector<Real>& sigma, Real plateau) {
  const Real half = plateau / 2;
  for (std::size_t k = x.size() - 1; k > 0; --k) {
    if (x[k - 1] <= 0) break;
    const bool beyond = (sigma[k] - half) * (plateau > 0 ? 1 : -1) < 0;
    const bool inside = (sigma[k - 1] - half) * (plateau > 0 ? 1 : -1) >= 0;
    if (beyond && inside) return x[k - 1] + (x[k] - x[k - 1]) * (half - sigma[k - 1]) / (sigma[k] - sigma[k - 1]);
  }
  return 0;
}

}  // namespace

CaseResult runCase(const Settings& settings, Real dx, const std::string& folder, bool writeFrames) {
  const Stopwatch setup;
  CaseResult result;
  const ParticleSet<1> particles = twoBars(settings.halfLength, dx);
  result.dx = dx;
  UpdatedLagrangianSph<1> system(particles, settings.options);
  const Index n = system.particleCount();
  const Material& material = settings.options.material;
  const Real c = material.pWaveSpeed(), rho = material.density(), v0 = settings.impactSpeed;
  const SymmetricBarImpact exact(settings.halfLength, c, rho, v0);

  Vector velocity(n);
  for (Index i = 0; i < n; ++i) velocity[i] = particles.position(i)[0] < 0 ? v0 : -v0;
  const Vector y0 = system.initialState(velocity);
  auto integrator = makeSolidIntegrator(system, y0, settings.integration, settings.endTime);

  EnergyLedger<1> ledger(system);
  SolidStateAdapter<1> adapter(system, particles);
  typename ParticleFrames<1>::Settings frameOptions;  // VTK frames only
  frameOptions.vtk = writeFrames && settings.output.vtk;
  frameOptions.extra = adapter.extraFields();
  ParticleFrames<1> frames(adapter.particles(), folder, "frame", frameOptions);
  frames.attachTo(adapter, settings.output.every);
  TimeLoop loop;
  loop.add(ledger, 20);
  loop.add(adapter);
  CaseRecord& record = result.record;
  record.setupSeconds = setup.seconds();
  const RunStatistics stats = loop.run(*integrator, settings.endTime);

  // Errors at the end time, at the particles' current positions.
  const Vector& y = integrator->solution();
  const Real t = integrator->time();
  const auto& layout = system.layout();
  std::vector<Real> x(static_cast<std::size_t>(n)), v(x.size()), sigma(x.size());
  Real errorV = 0, normV = 0, errorS = 0, normS = 0, plateauSum = 0, plateauCount = 0;
  AtomicFile profile(folder + "/" + profileFileName(dx));
  profile.stream() << "x [m],v [m/s],v_exact [m/s],sigma [Pa],sigma_exact [Pa]\n" << std::setprecision(12);
  for (Index i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    x[k] = y[layout.position(i, 0)];
    v[k] = y[layout.velocity(i, 0)];
    sigma[k] = system.stress(y, i)(0, 0);
    const Real ve = exact.velocity(x[k], t), se = exact.stress(x[k], t);
    errorV += std::abs(v[k] - ve);
    normV += std::abs(ve);
    errorS += std::abs(sigma[k] - se);
    normS += std::abs(se);
    if (std::abs(x[k]) < settings.plateauFraction * c * t) {
      plateauSum += sigma[k];
      plateauCount += 1;
    }
    profile.stream() << x[k] << ',' << v[k] << ',' << ve << ',' << sigma[k] << ',' << se << '\n';
  }
  profile.commit();

  std::ostringstream name;
  name << "dx = " << dx;
  record.name = name.str();
  record.particles = n;
  result.recordLoop(stats);
  record.timeStep = integrator->stepSize();  // the last step
  // The step is cfl times the method's step criteria unless a fixed step was asked for.
  if (settings.integration.fixedStep <= 0) record.stableTimeStep = record.timeStep / settings.integration.cfl;
  record.simulatedTime = settings.endTime;
  result.meanNeighbours = system.meanNeighbourCount();
  result.l1Velocity = errorV / normV;
  result.l1Stress = errorS / normS;
  result.plateauStressError = plateauCount > 0 ? plateauSum / plateauCount / exact.interfaceStress() - 1 : std::nan("");
  result.frontErrorOverDx = (measuredFront(x, sigma, exact.interfaceStress()) - exact.frontPosition(t)) / dx;
  result.balanceDrift = ledger.largestBalanceDrift();
  // The frame series, whichever case writes it (the one at geometry.spacing).
  frames.report().appendTo(result.files, result.notes);
  record.errors = {{"l1_velocity", result.l1Velocity},
                   {"l1_stress", result.l1Stress},
                   {"plateau_stress_error", result.plateauStressError},
                   {"front_error_over_dx", result.frontErrorOverDx}};
  record.primaryError = "l1_velocity";
  result.files.push_back(profileFileName(dx));
  return result;
}

}  // namespace mfwave::bar1dsph
