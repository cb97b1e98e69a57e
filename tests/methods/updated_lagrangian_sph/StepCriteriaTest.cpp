#include "UlsphTestSupport.hpp"
#include "core/Error.hpp"
#include "particles/Lattice.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfwave;

// The step criteria read what the last right-hand side evaluation computed (viscous signal speeds,
// accelerations). Before any evaluation there is nothing to read: refused, not a silently longer
// step. evaluateStepCriteria makes the evaluation and gives what stableStep then gives.
TEST(UlsphStepCriteria, NeedAnEvaluationAndAgreeWithTheStepRuleAfterIt) {
  const ParticleSet<1> line = makeLine(0, 1, 0.02);
  UpdatedLagrangianSphOptions options;
  options.material = Material::fromLame(1.0, 1.0, 1.0);
  UpdatedLagrangianSph<1> system(line, options);
  Vector v(system.particleCount());
  for (Index i = 0; i < v.size(); ++i) v[i] = 0.01 * std::sin(3.0 * static_cast<Real>(i));
  const Vector y0 = system.initialState(v);
  EXPECT_THROW(system.stableStep(y0), Error);

  const Real first = system.evaluateStepCriteria(0, y0);
  EXPECT_GT(first, 0);
  EXPECT_EQ(first, system.stableStep(y0));
  // The Courant criterion alone bounds it: courant h / c_p with c_p at least sqrt((lambda + 2 mu) / rho).
  const Real cp = std::sqrt(3.0);
  EXPECT_LE(first, options.courant * system.smoothingLength() / cp * (1 + 1e-12));
}
