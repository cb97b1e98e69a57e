// The smallest program on mfwave as a library: a lattice block (7 x 7 x 7 at spacing 0.5, two
// ghost layers, all faces free), the very weak form SPH operator on it, a vertical velocity pulse
// under the top face, central difference at half the safe step, and a probe of the vertical
// velocity at the top centre. Prints the probe's last value; scripts/check-install.sh compares it
// with the value the in-tree build gives.

#include "numerics/StableTimeStep.hpp"
#include "integrators/CentralDifference.hpp"
#include "kernels/CubicSplineKernel.hpp"
#include "methods/very_weak_sph/VeryWeakSph.hpp"
#include "neighbours/NeighbourList.hpp"
#include "observers/ProbeRecorder.hpp"
#include "observers/TimeLoop.hpp"
#include "particles/BoxFace.hpp"
#include "particles/GhostLayers.hpp"
#include "particles/Lattice.hpp"

#include <cmath>
#include <cstdio>

using namespace mfwave;

int main() {
  const Real dx = 0.5;
  const Vec3 lower = Vec3::Zero(), upper = Vec3::Constant(7);
  ParticleSet<3> particles = makeLattice<3>(lower, upper, dx);
  addGhostLayers<3>(particles, lower, upper, dx, 2, allFaces(3));
  const CubicSplineKernel kernel(3, dx);
  const NeighbourList neighbours =
      buildNeighbourList(CellList<3>(particles, kernel.supportRadius()), particles.physicalCount());
  VeryWeakSph<3> method = assembleVeryWeakSph(particles, neighbours, kernel, VeryWeakSphOptions{});

  const Index n = particles.physicalCount();
  const Vec3 top(3.5, 3.5, 7.0);
  Index probed = 0;
  Vector u0 = Vector::Zero(3 * n), v0 = Vector::Zero(3 * n);
  for (Index a = 0; a < n; ++a) {
    const Vec3 x = particles.position(a);
    v0[3 * a + 2] = std::exp(-(x - Vec3(3.5, 3.5, 5.5)).squaredNorm());
    if ((x - top).norm() < (particles.position(probed) - top).norm()) probed = a;
  }

  CentralDifference integrator;
  integrator.initialise(method.system, 0.0, u0, v0, 0.5 * centralDifferenceSafeStep(method.system));
  ProbeRecorder probe({{"top_centre", probed, 2, ProbeQuantity::Velocity}}, 3);
  TimeLoop loop;
  loop.add(probe);
  const RunStatistics run = loop.run(integrator, 4.0);

  std::printf("particles %lld, steps %ld, t = %.6f\n", static_cast<long long>(n), run.steps, integrator.time());
  std::printf("probe top_centre v_z = %.12e\n", probe.series().column(0).back());
  return 0;
}
