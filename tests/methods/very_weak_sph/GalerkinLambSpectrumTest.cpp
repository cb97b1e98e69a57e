// The whole bounded Lamb operator of the Galerkin variant (issue 15) at the study's two coarser
// spacings, by an iterative eigensolver on the assembled matrices. A sparse Cholesky factorisation
// of 73,000 unknowns takes about a minute here, so this runs with the study tests, not under the
// sanitizers.

#include "numerics/LowestModes.hpp"
#include "numerics/StableTimeStep.hpp"
#include "methods/very_weak_sph/VeryWeakSph.hpp"
#include "kernels/CubicSplineKernel.hpp"
#include "particles/Lattice.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <iostream>

namespace mfwave {
namespace {

// The whole bounded Lamb operator at the study's two coarser spacings, by an iterative eigensolver
// on the assembled matrices (LowestModes.hpp): K + 1e-10 omega_max^2 M factorises (no eigenvalue of
// M^-1 K below -1e-10 omega_max^2), its six lowest eigenvalues are the rigid-body modes (zero to
// round-off) and the seventh is an elastic mode well above round-off. With the dashpots symmetric
// positive semi-definite (previous test) no mode of M u'' + C u' + K u = 0 can grow.
TEST(GalerkinLattice, LambOperatorsAtHalfAndQuarterSpacingHaveOnlyRigidModesAtTheBottom) {
  for (const Real dx : {0.5, 0.25}) {
    const ParticleSet<3> particles = makeBlock(Vec3(-3.5, -3.5, -7.0), Vec3(3.5, 3.5, 0.0), dx);
    VeryWeakSphOptions options;
    options.variant = VeryWeakSphVariant::Galerkin;
    options.material = Material::fromLame(1, 1, 1);
    VeryWeakSph<3> method = assembleVeryWeakSph<3>(particles, NeighbourList(), CubicSplineKernel(3, 1.0), options);
    const Real omegaMax = std::pow(2 / centralDifferenceStableStep(method.system, 1e-6, 5000).estimate(), 2);
    const Vector mass = method.system.mass().diagonal();
    const auto start = std::chrono::steady_clock::now();
    const LowestModes modes = lowestModes(method.system.stiffness(), mass, 8, 1e-10 * omegaMax, 1e-8);
    ASSERT_TRUE(modes.shiftedMatrixPositiveDefinite) << "dx = " << dx;
    EXPECT_TRUE(modes.converged) << "dx = " << dx << ", " << modes.iterations << " iterations";
    std::cout << "dx = " << dx << ": omega_max^2 = " << omegaMax << ", lowest eigenvalues / omega_max^2:";
    for (const Real lambda : modes.eigenvalues) std::cout << ' ' << lambda / omegaMax;
    std::cout << " (" << modes.iterations << " iterations, "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s)\n";
    for (int k = 0; k < 6; ++k) EXPECT_LT(std::abs(modes.eigenvalues[static_cast<std::size_t>(k)]), 1e-11 * omegaMax);
    EXPECT_GT(modes.eigenvalues[6], 1e-5 * omegaMax);
  }
}

}  // namespace
}  // namespace mfwave
