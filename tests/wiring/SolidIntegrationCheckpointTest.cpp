// Checkpoints of an updated-Lagrangian SPH run (issue 20): a run wired as the studies wire it
// (makeSolidIntegrator: the method's step criteria before every step), saved after N steps and
// restored into a freshly built system and integrator, goes on bit for bit as the run that never
// stopped, and so does the energy ledger the studies add (whose zero-energy-mode indicator
// refreshes the system's neighbour lists between steps). The restored state has to carry more than y: the step criteria of the last momentum
// evaluation (largest mu_ij, accelerations; without them the next step size differs) and the
// neighbour lists kept between rebuilds (without them the rebuild count and the lists differ).

#include "core/Error.hpp"
#include "core/StateArchive.hpp"
#include "methods/updated_lagrangian_sph/UpdatedLagrangianSph.hpp"
#include "particles/Lattice.hpp"
#include "wiring/EnergyLedger.hpp"
#include "wiring/SolidIntegration.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

using namespace mfwave;

namespace {

constexpr Real kPi = 3.14159265358979323846;

// A block 0.6 x 0.3 sheared and squeezed fast enough that particles pass half the skin every few
// steps: rebuilds happen before and after the checkpoint.
struct StudyRun {
  explicit StudyRun(const std::string& integratorName) : system(block(), options()), ledger(system) {
    const Index n = system.particleCount();
    Vector velocity(2 * n);
    const ParticleSet<2> particles = block();
    for (Index i = 0; i < n; ++i) {
      const Vec2 x = particles.position(i);
      velocity[2 * i] = 0.2 * std::sin(kPi * x[1] / 0.3);
      velocity[2 * i + 1] = 0.1 * std::cos(kPi * x[0] / 0.6);
    }
    SolidIntegrationSettings settings;
    settings.integrator = integratorName;
    settings.cfl = 0.9;
    integrator = makeSolidIntegrator(system, system.initialState(velocity), settings, 1.0);
  }

  // As TimeLoop: begin() before the first step (not on a restart), the ledger after every step.
  void begin() { ledger.begin(integrator->state()); }

  static ParticleSet<2> block() { return makeLattice<2>(Vec2::Zero(), Vec2(0.6, 0.3), 0.03); }

  static UpdatedLagrangianSphOptions options() {
    UpdatedLagrangianSphOptions o;
    o.viscosity.alpha = 0.5;
    o.viscosity.beta = 1;  // the step's viscous criterion reads the largest mu_ij
    o.artificialStress.enabled = true;
    o.xsph = 0.5;
    o.density = DensityUpdate::Summation;  // stableStep sums densities over the kept lists
    return o;
  }

  void steps(int count) {
    for (int k = 0; k < count; ++k) {
      integrator->step();
      ledger.observe(integrator->state());
    }
  }

  UpdatedLagrangianSph<2> system;
  EnergyLedger<2> ledger;
  std::unique_ptr<FirstOrderIntegrator> integrator;
};

void expectBitwiseEqual(const StudyRun& restarted, const StudyRun& reference) {
  ASSERT_EQ(restarted.integrator->stepCount(), reference.integrator->stepCount());
  EXPECT_EQ(restarted.integrator->time(), reference.integrator->time());
  EXPECT_EQ(restarted.integrator->stepSize(), reference.integrator->stepSize());
  const Vector& y = restarted.integrator->solution();
  const Vector& expected = reference.integrator->solution();
  ASSERT_EQ(y.size(), expected.size());
  Index differing = 0;
  for (Index k = 0; k < y.size(); ++k)
    if (y[k] != expected[k]) ++differing;
  EXPECT_EQ(differing, 0) << "of " << y.size() << " state entries";
  EXPECT_EQ(restarted.system.neighbourRebuilds(), reference.system.neighbourRebuilds());
  EXPECT_EQ(restarted.system.neighbours().offsets, reference.system.neighbours().offsets);
  EXPECT_EQ(restarted.system.neighbours().indices, reference.system.neighbours().indices);
  const TimeSeries& energy = restarted.ledger.series();
  const TimeSeries& expectedEnergy = reference.ledger.series();
  EXPECT_EQ(energy.times(), expectedEnergy.times());
  for (std::size_t c = 0; c < expectedEnergy.columns(); ++c) {
    EXPECT_EQ(energy.column(c), expectedEnergy.column(c)) << expectedEnergy.names()[c];
  }
  EXPECT_EQ(restarted.ledger.initialEnergy(), reference.ledger.initialEnergy());
  EXPECT_EQ(restarted.ledger.largestBalanceDrift(), reference.ledger.largestBalanceDrift());
}

void checkRestart(const std::string& integratorName) {
  constexpr int N = 23, M = 17;
  StudyRun reference(integratorName);
  reference.begin();
  reference.steps(N);
  const long rebuildsAtCheckpoint = reference.system.neighbourRebuilds();
  reference.steps(M);
  // The test means something only if the lists were rebuilt before the checkpoint (the restored
  // system's own lists are those of y0) and again after it.
  EXPECT_GT(rebuildsAtCheckpoint, 1);
  EXPECT_GT(reference.system.neighbourRebuilds(), rebuildsAtCheckpoint);

  StateArchive archive;
  {
    StudyRun interrupted(integratorName);
    interrupted.begin();
    interrupted.steps(N);
    StateArchive integratorPart = archive.section("integrator");
    StateArchive ledgerPart = archive.section("ledger");
    interrupted.integrator->saveState(integratorPart);
    interrupted.ledger.saveState(ledgerPart);
  }
  StudyRun restarted(integratorName);
  restarted.integrator->restoreState(archive.section("integrator"));
  restarted.ledger.restoreState(archive.section("ledger"));
  EXPECT_EQ(restarted.system.neighbourRebuilds(), rebuildsAtCheckpoint);
  restarted.steps(M);
  expectBitwiseEqual(restarted, reference);
}

}  // namespace

TEST(SolidIntegrationCheckpoint, LeapfrogWithTheStepRuleRestartsBitwise) { checkRestart("leapfrog"); }

TEST(SolidIntegrationCheckpoint, PredictorCorrectorWithTheStepRuleRestartsBitwise) {
  checkRestart("predictor_corrector");
}

// A checkpoint of another particle count is refused by name, not restored into nonsense.
TEST(SolidIntegrationCheckpoint, ACheckpointOfAnotherSystemIsRefused) {
  UpdatedLagrangianSph<2> small(makeLattice<2>(Vec2::Zero(), Vec2(0.3, 0.3), 0.03), StudyRun::options());
  small.evaluateStepCriteria(0, small.initialState());
  StateArchive archive;
  small.saveState(archive);
  StudyRun other("leapfrog");
  EXPECT_THROW(other.system.restoreState(archive), InputError);
}
