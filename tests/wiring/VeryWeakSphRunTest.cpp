// lib/wiring/VeryWeakSphRun: the central-difference integrator of a very weak SPH problem honours its
// prescribed faces (eq. 30) and applies its smoothing (eq. 33), booking what the filter removes in
// the energy ledger without changing the run; the probes report the state and, with the published
// variant's deconvolution, the deconvolved value (eq. 35); the growth message names each variant's
// cause and key.

#include "core/Error.hpp"
#include "methods/very_weak_sph/Deconvolution.hpp"
#include "observers/TimeLoop.hpp"
#include "particles/BoxFace.hpp"
#include "particles/GhostLayers.hpp"
#include "particles/Lattice.hpp"
#include "wiring/VeryWeakSphRun.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace mfwave {
namespace {

constexpr Real kDx = 0.25;
const Vec2 kLower(0, 0), kUpper(2, 1.5);

ParticleSet<2> plate() {
  ParticleSet<2> particles = makeLattice<2>(kLower, kUpper, kDx);
  addGhostLayers<2>(particles, kLower, kUpper, kDx, 2, allFaces(2));
  return particles;
}

VeryWeakSphProblemSettings<2> publishedSettings(Real smoothingRate, bool deconvolution) {
  VeryWeakSphProblemSettings<2> s;
  s.options.material = Material::fromLame(1.0, 1.0, 1.0);
  s.options.variant = VeryWeakSphVariant::Published;
  s.smoothingLength = 1.2 * kDx;
  s.lower = kLower;
  s.upper = kUpper;
  s.spacing = kDx;
  s.smoothingRate = smoothingRate;
  s.deconvolution = deconvolution;
  return s;
}

// A smooth, non-zero start: every particle moves.
Vector startVelocity(const ParticleSet<2>& particles) {
  Vector v(2 * particles.physicalCount());
  for (Index a = 0; a < particles.physicalCount(); ++a) {
    const Vec2 x = particles.position(a);
    v[2 * a] = std::sin(2 * x[0] + x[1]);
    v[2 * a + 1] = std::cos(x[0] - 3 * x[1]);
  }
  return v;
}

TEST(VeryWeakSphCentralDifference, HoldsPrescribedFacesAtTheirValues) {
  const ParticleSet<2> particles = plate();
  const TimeFunction ramp = TimeFunction::ramp(0, 1.0);
  VeryWeakSphProblemSettings<2> settings = publishedSettings(0, false);
  settings.prescribed.push_back({faceBit(BoxFace::MinusX), Vec2(0.01, -0.02), &ramp});
  VeryWeakSphProblem<2> problem(particles, settings);
  const auto integrator = veryWeakSphCentralDifference<2>(problem);
  const Real dt = 0.01;
  integrator->initialise(problem.system(), 0, problem.initialDisplacement(), startVelocity(particles), dt);
  for (int step = 0; step < 30; ++step) integrator->step();
  const StateView s = integrator->state();
  Vector g(static_cast<Index>(problem.prescribedDofs().size()));
  problem.prescribedValues(s.time, g);
  ASSERT_GT(g.size(), 0);
  EXPECT_GT(g.cwiseAbs().maxCoeff(), 0.0);  // the ramp has risen: the values are not trivially zero
  for (std::size_t k = 0; k < problem.prescribedDofs().size(); ++k)
    EXPECT_NEAR(s.displacement[problem.prescribedDofs()[k]], g[static_cast<Index>(k)], 1e-15);
}

// Runs 40 steps of the filtered published problem; returns the final velocity.
Vector runFiltered(LinearEnergyLedger* ledger) {
  const ParticleSet<2> particles = plate();
  VeryWeakSphProblem<2> problem(particles, publishedSettings(2.0, false));
  const auto integrator = veryWeakSphCentralDifference<2>(problem, ledger);
  integrator->initialise(problem.system(), 0, Vector::Zero(problem.system().size()), startVelocity(particles), 0.01);
  TimeLoop loop;
  if (ledger) loop.add(*ledger);
  loop.run(*integrator, 0.4);
  return integrator->state().velocity;
}

TEST(VeryWeakSphCentralDifference, AppliesTheSmoothingAndBooksItsLossInTheLedger) {
  const ParticleSet<2> particles = plate();
  VeryWeakSphProblem<2> problem(particles, publishedSettings(2.0, false));
  LinearEnergyLedgerOptions options;
  options.components = 2;
  options.balanceLimit = 0;
  options.stop = false;
  LinearEnergyLedger ledger(problem.system(), options);
  const Vector withLedger = runFiltered(&ledger);
  const Vector without = runFiltered(nullptr);
  EXPECT_EQ((withLedger - without).norm(), 0.0);  // the ledger only books
  const std::vector<Real> loss = ledger.series().column(LinearEnergyLedger::FilterLoss);
  ASSERT_FALSE(loss.empty());
  EXPECT_GT(loss.back(), 1e-6 * ledger.largestEnergy());

  // Without the filter the same run ends elsewhere: the filter did act.
  VeryWeakSphProblem<2> unfiltered(particles, publishedSettings(0, false));
  const auto plain = veryWeakSphCentralDifference<2>(unfiltered);
  plain->initialise(unfiltered.system(), 0, Vector::Zero(unfiltered.system().size()), startVelocity(particles), 0.01);
  TimeLoop loop;
  loop.run(*plain, 0.4);
  EXPECT_GT((plain->state().velocity - without).norm(), 1e-6 * without.norm());
}

TEST(VeryWeakSphProbes, ReportTheStateOrItsDeconvolutionOncePerTime) {
  const ParticleSet<2> particles = plate();
  VeryWeakSphProblem<2> problem(particles, publishedSettings(0, true));
  ASSERT_NE(problem.deconvolution(), nullptr);
  const Index probeParticle = 12;
  const std::vector<Probe> probes{{"a", probeParticle, 1, ProbeQuantity::Velocity},
                                  {"b", probeParticle, 0, ProbeQuantity::Displacement}};
  const ParticleMatrix rows = problem.deconvolutionRows({probeParticle, probeParticle}, {1, 0});
  ASSERT_EQ(rows.rows(), 2);
  VeryWeakSphProbes sharp(probes, 2, &rows);
  VeryWeakSphProbes plain(probes, 2, nullptr);
  const Vector u = 0.5 * startVelocity(particles), v = startVelocity(particles);
  const StateView s{1, 0.25, u, v};
  sharp.observe(s);
  plain.observe(s);
  sharp.end(s);  // the same time again: no second sample
  ASSERT_EQ(sharp.times().size(), 1u);
  EXPECT_EQ(sharp.raw(0)[0], v[2 * probeParticle + 1]);
  EXPECT_EQ(sharp.raw(1)[0], u[2 * probeParticle]);
  EXPECT_EQ(plain.reported(0)[0], plain.raw(0)[0]);
  EXPECT_EQ(sharp.reported(0)[0], deconvolveAt(*problem.deconvolution(), probeParticle, v, 2, 1));
  EXPECT_EQ(sharp.reported(1)[0], deconvolveAt(*problem.deconvolution(), probeParticle, u, 2, 0));
  EXPECT_NE(sharp.reported(0)[0], sharp.raw(0)[0]);

  const std::string path = ::testing::TempDir() + "/probes-" + std::to_string(::getpid()) + ".csv";
  sharp.writeCsv(path, {{1.5}, {}});
  std::ifstream in(path);
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  EXPECT_EQ(header, "t [s],a_raw,a_reported,a_exact,b_raw,b_reported");
  EXPECT_EQ(std::count(row.begin(), row.end(), ','), 5);
  EXPECT_EQ(row.substr(0, 5), "0.25,");
  std::remove(path.c_str());
}

TEST(VeryWeakSphGrowthCause, NamesEachVariantsCauseAndKey) {
  EXPECT_NE(veryWeakSphGrowthCause(VeryWeakSphVariant::Galerkin).find("integrator.cfl"), std::string::npos);
  EXPECT_NE(veryWeakSphGrowthCause(VeryWeakSphVariant::Consistent).find("stability.allow_growth"), std::string::npos);
  EXPECT_NE(veryWeakSphGrowthCause(VeryWeakSphVariant::Published).find("method.smoothing_rate"), std::string::npos);
}

}  // namespace
}  // namespace mfwave
