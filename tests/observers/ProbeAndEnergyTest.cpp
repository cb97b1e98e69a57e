#include "support/ScriptedIntegrator.hpp"
#include "core/Error.hpp"
#include "observers/EnergyObserver.hpp"
#include "observers/ProbeRecorder.hpp"
#include "observers/TimeLoop.hpp"
#include "systems/LinearSecondOrderSystem.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

using namespace mfwave;
using mfwave::testing::ScriptedIntegrator;

TEST(ProbeRecorder, RecordsTheChosenComponentsWithUnitsInTheHeader) {
  // Two particles with 2 components: u = (step, 10 step, 100 step, 1000 step), v = -u.
  ScriptedIntegrator integrator(Vector::Zero(4), Vector::Zero(4), 0.25, [](long step, Vector& u, Vector& v) {
    u << 1, 10, 100, 1000;
    u *= static_cast<Real>(step);
    v = -u;
  });
  ProbeRecorder probes({{"left", 0, 1, ProbeQuantity::Displacement}, {"right", 1, 0, ProbeQuantity::Velocity}}, 2);
  TimeLoop loop;
  loop.add(probes, 2);
  loop.run(integrator, 1.0);
  const TimeSeries& series = probes.series();
  ASSERT_EQ(series.rows(), 3u);  // steps 0, 2, 4
  EXPECT_EQ(series.column(0), (std::vector<Real>{0, 20, 40}));
  EXPECT_EQ(series.column(1), (std::vector<Real>{0, -200, -400}));
  EXPECT_EQ(series.names()[0], "left u_y [m]");
  EXPECT_EQ(series.names()[1], "right v_x [m/s]");

  const auto path = std::filesystem::temp_directory_path() / "mfwave-probe-test.csv";
  series.writeCsv(path.string());
  std::ifstream in(path);
  std::string header, first;
  std::getline(in, header);
  std::getline(in, first);
  EXPECT_EQ(header, "time [s],left u_y [m],right v_x [m/s]");
  EXPECT_EQ(first, "0,0,0");
}

TEST(ProbeRecorder, AProbeOutsideTheStateNamesItsKey) {
  ScriptedIntegrator integrator(Vector::Zero(4), Vector::Zero(4), 1, [](long, Vector&, Vector&) {});
  ProbeRecorder probes({{"far", 7, 0, ProbeQuantity::Velocity}}, 2);
  TimeLoop loop;
  loop.add(probes);
  try {
    loop.run(integrator, 1);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "probe[0].particle");
  }
  EXPECT_THROW(ProbeRecorder({{"bad", 0, 3, ProbeQuantity::Velocity}}, 3), InputError);
}

TEST(EnergyObserver, MeasuresDriftOfALinearSystem) {
  // u'' + u = 0 with M = 1, K = 1: the exact motion u = cos t, v = -sin t keeps E = 1/2.
  // The scripted motion adds a 1 % amplitude error at the end to check the drift measure.
  SparseMatrix one(1, 1);
  one.insert(0, 0) = 1;
  LinearSecondOrderSystem system(one, SparseMatrix(), one);
  ScriptedIntegrator integrator(Vector::Ones(1), Vector::Zero(1), 0.1, [](long step, Vector& u, Vector& v) {
    const Real t = 0.1 * static_cast<Real>(step);
    const Real amplitude = step == 30 ? 1.01 : 1.0;
    u[0] = amplitude * std::cos(t);
    v[0] = -amplitude * std::sin(t);
  });
  EnergyObserver energy(EnergyObserver::ofLinearSystem(system));
  TimeLoop loop;
  loop.add(energy);
  loop.run(integrator, 3.0);
  EXPECT_NEAR(energy.series().column(2).front(), 0.5, 1e-15);
  EXPECT_NEAR(energy.maxRelativeDrift(), 1.01 * 1.01 - 1, 1e-12);
}
