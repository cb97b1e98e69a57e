// How much of a P pulse the transmitting boundary (Ding-Long-Wu eqs. (31)-(32)) sends back: the
// energy left in the domain after the pulse has met the boundary, over the energy before, measured
// with the published scheme and compared with the Lysmer-Kuhlemeyer theory of the continuous
// dashpot boundary (derived below).
//
// Lysmer-Kuhlemeyer theory. Half-space with outward unit normal n at the boundary, dashpot traction
// sigma n = -rho Z v, Z = c_p n n^T + c_s (I - n n^T). A plane wave u = a p exp(i w (s.x - t)) (slowness
// s, unit polarisation p) has traction sigma n = i w a [lambda (s.p) n + mu (s (p.n) + p (s.n))] and
// velocity -i w a p, so the boundary condition is sum_j a_j g_j = 0 with
//   g_j = lambda (s_j.p_j) n + mu (s_j (p_j.n) + p_j (s_j.n)) - rho Z p_j.
// Incident P at angle theta from n (a_0 = 1), reflected P (a_1 = R_P) and SV (a_2 = R_S) share the
// tangential slowness sin(theta)/c_p (Snell: sin(phi) = c_s sin(theta)/c_p); in the frame (t, n):
//   s_0 = (sin th, cos th)/c_p, p_0 = c_p s_0;  s_1 = (sin th, -cos th)/c_p, p_1 = c_p s_1;
//   s_2 = (sin ph, -cos ph)/c_s, p_2 = (cos ph, sin ph).
// [g_1 g_2] (R_P, R_S)^T = -g_0 is a 2 x 2 system. The energy flux through the boundary of a plane
// wave is rho w^2 |a|^2 c cos(angle)/2, so the reflected energy fraction is
//   E_R = R_P^2 + (c_s cos ph) / (c_p cos th) R_S^2.
// At normal incidence g_0 = ((lambda + 2 mu)/c_p - rho c_p) n = 0: nothing is reflected. With Z = 0
// (free surface) E_R = 1 for every angle, a check of the algebra. The coefficients do not depend on
// frequency, so E_R is also the reflected fraction of any pulse.

#include "BlockFixture.hpp"

#include "numerics/StableTimeStep.hpp"
#include "core/Material.hpp"
#include "integrators/CentralDifference.hpp"
#include "methods/very_weak_sph/TransmittingBoundary.hpp"
#include "methods/very_weak_sph/VeryWeakSph.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace mfwave;
using mfwave::test::Block;

namespace {

struct Reflection {
  Real pAmplitude;   // R_P
  Real sAmplitude;   // R_S
  Real energy;       // E_R
};

// Plane P wave at angle theta on a boundary with the continuous Lysmer-Kuhlemeyer dashpots
// (dashpots = false: a free surface), in the frame (tangent, normal).
Reflection lysmerKuhlemeyerReflection(const Material& m, Real theta, bool dashpots = true) {
  const Real cp = m.pWaveSpeed(), cs = m.sWaveSpeed();
  const Real phi = std::asin(cs * std::sin(theta) / cp);
  const Vec2 n(0, 1);
  const Mat2 z = dashpots ? dashpotImpedance<2>(m, n) : Mat2::Zero();
  auto g = [&](const Vec2& s, const Vec2& p) -> Vec2 {
    return m.lambda() * s.dot(p) * n + m.mu() * (s * p.dot(n) + p * s.dot(n)) - m.density() * z * p;
  };
  const Vec2 s0(std::sin(theta) / cp, std::cos(theta) / cp);
  const Vec2 s1(std::sin(theta) / cp, -std::cos(theta) / cp);
  const Vec2 s2(std::sin(phi) / cs, -std::cos(phi) / cs);
  Mat2 system;
  system.col(0) = g(s1, Vec2(cp * s1));
  system.col(1) = g(s2, Vec2(std::cos(phi), std::sin(phi)));
  const Vec2 r = system.partialPivLu().solve(Vec2(-g(s0, Vec2(cp * s0))));
  return {r[0], r[1], r[0] * r[0] + cs * std::cos(phi) / (cp * std::cos(theta)) * r[1] * r[1]};
}

Real energy(const LinearSecondOrderSystem& system, const Vector& u, const Vector& v) {
  return system.kineticEnergy(v) + system.strainEnergy(u);
}

// Runs `system` from (u0, v0) with central difference (eq. (32): implicit dashpots) to time tEnd and
// returns E(tEnd) / E(0).
Real energyFraction(LinearSecondOrderSystem& system, const Vector& u0, const Vector& v0, Real tEnd) {
  const Real dt0 = 0.9 * centralDifferenceSafeStep(system);
  const int steps = static_cast<int>(std::ceil(tEnd / dt0));
  CentralDifference integrator;
  integrator.initialise(system, 0.0, u0, v0, tEnd / steps);
  for (int step = 0; step < steps; ++step) integrator.step();
  return energy(system, integrator.state().displacement, integrator.state().velocity) / energy(system, u0, v0);
}

}  // namespace

TEST(TransmittingAbsorption, LysmerKuhlemeyerTheoryForPoissonSolid) {
  const Material m = Material::fromLame(1, 1, 1);  // nu = 1/4
  std::printf("theta  R_P        R_S        E_R (LK dashpots)   E_R (free)\n");
  for (Real degrees : {0.0, 15.0, 30.0, 45.0, 60.0, 75.0}) {
    const Real theta = degrees * M_PI / 180;
    const Reflection lk = lysmerKuhlemeyerReflection(m, theta);
    const Reflection free = lysmerKuhlemeyerReflection(m, theta, false);
    std::printf("%5.1f  %+.6f  %+.6f  %.6f            %.12f\n", degrees, lk.pAmplitude, lk.sAmplitude, lk.energy,
                free.energy);
    EXPECT_NEAR(free.energy, 1.0, 1e-12);  // energy balance of the algebra
  }
  EXPECT_NEAR(lysmerKuhlemeyerReflection(m, 0).energy, 0.0, 1e-30);
  // Values from an independent scalar evaluation of the same 2 x 2 system (written out by components).
  EXPECT_NEAR(lysmerKuhlemeyerReflection(m, M_PI / 12).energy, 0.000162152127, 1e-12);
  EXPECT_NEAR(lysmerKuhlemeyerReflection(m, M_PI / 6).energy, 0.0003083037147, 1e-12);
  EXPECT_NEAR(lysmerKuhlemeyerReflection(m, M_PI / 4).energy, 0.003937749818, 1e-11);
  // At 60 degrees R_P = R_S = -(1 - sqrt(3)/2) for nu = 1/4.
  EXPECT_NEAR(lysmerKuhlemeyerReflection(m, M_PI / 3).pAmplitude, -(1 - std::sqrt(3.0) / 2), 1e-12);
  EXPECT_NEAR(lysmerKuhlemeyerReflection(m, M_PI / 3).sAmplitude, -(1 - std::sqrt(3.0) / 2), 1e-12);
}

TEST(TransmittingAbsorption, OneDimensionalBarNormalIncidence) {
  // Bar [0, 200], dx = h = 1, two ghost layers; lambda = mu = rho = 1 (modulus 3, c_p = sqrt(3)).
  // A right-moving Gaussian P pulse u = g(x - 100), v = -c_p g', g = exp(-x^2 / (2 sigma^2)),
  // sigma = 4 h, meets the right end at t = 100 / c_p; at t = 150 / c_p a free-end echo would be back
  // at x = 150, far from both ends. The left end is free in every run.
  const Real dx = 1, width = 4;
  const Block<1> block(Vec1(0), Vec1(200), dx, 2, dx);
  VeryWeakSphOptions options;
  const Material& m = options.material;
  const Index n = block.particles.physicalCount();
  Vector u0(n), v0(n);
  for (Index a = 0; a < n; ++a) {
    const Real x = block.particles.position(a)[0] - 100;
    const Real g = std::exp(-x * x / (2 * width * width));
    u0[a] = g;
    v0[a] = m.pWaveSpeed() * x / (width * width) * g;  // -c_p g'(x)
  }
  const Real tEnd = 150 / m.pWaveSpeed();
  Real fraction[3];
  const char* names[3] = {"free", "particle", "consistent"};
  for (int run = 0; run < 3; ++run) {
    VeryWeakSph<1> vw = assembleVeryWeakSph(block.particles, block.neighbours, block.kernel, options);
    if (run > 0) {
      const SparseMatrix c = assembleTransmittingDamping(
          block.particles, block.neighbours, block.kernel, vw.data.facets, m, faceBit(BoxFace::PlusX),
          run == 1 ? DashpotLumping::Particle : DashpotLumping::Consistent);
      vw.system.setDamping(c);
    }
    fraction[run] = energyFraction(vw.system, u0, v0, tEnd);
    std::printf("1-D bar, %-10s right end: E(t = 150/c_p) / E(0) = %.6f\n", names[run], fraction[run]);
  }
  // Measured: free 1.000179, particle 0.036968, consistent 0.008006 (deterministic; asserted to 1e-5).
  EXPECT_NEAR(fraction[0], 1.000179, 1e-5);
  EXPECT_NEAR(fraction[1], 0.036968, 1e-5);
  EXPECT_NEAR(fraction[2], 0.008006, 1e-5);
  // Why not zero: the continuous 1-D dashpot is exact, but the discrete one is weaker than rho c_p.
  // Its force on the bar is the dashpot rate summed over the rows it reaches, each row counting
  // V_a alpha_a = dx (eqs. (25), (29) on a lattice): Particle lumping keeps only the end row,
  // dx W(0) A rho c_p = 2/3 rho c_p at h = dx (1-D cubic spline W(0) = 2/(3h), A = 1); Consistent adds
  // the next row, dx W(dx) A rho c_p = 1/6 rho c_p, so 5/6 rho c_p. A dashpot of r rho c_p reflects
  // ((1 - r) / (1 + r))^2 of the energy: 1/25 = 0.04 and 1/121 = 0.0083, which the runs reproduce.
  EXPECT_NEAR(fraction[1], 1.0 / 25, 0.005);
  EXPECT_NEAR(fraction[2], 1.0 / 121, 0.001);
  EXPECT_LT(fraction[1], 0.05);  // against 1.0002 for the free end
}

namespace {

// A Gaussian-windowed plane P pulse in plane strain, travelling at `theta` from the normal towards
// the transmitting -y face of a rectangle that is large enough for every reflected wave to have left
// that face, and for no wave to have reached another face, at the end of the run. dx = h = 1.
// Returns E(t_end) / E(0) with the -y face transmitting (or free).
Real obliqueReflectedFraction(Real theta, DashpotLumping lumping, bool transmitting, Index* particleCount) {
  const Material m = Material::fromLame(1, 1, 1);
  const Real cp = m.pWaveSpeed(), cs = m.sWaveSpeed();
  // Pulse: u = d g(xi) w(eta), v = -c_p d g'(xi) w(eta); xi along d, eta across it; g a Ricker
  // wavelet of width `width`, w a Gaussian window of standard deviation `window`, both cut at 3 of
  // them for the geometry. Not a plain Gaussian g: its mean displacement is not zero, and on the 2-D
  // lattice the operator's nonzero row sum (the spurious 'elastic foundation' of the published
  // scheme) keeps the long-wave part oscillating in place, where it counts as reflected (measured
  // with a Gaussian g: 0.18 at normal incidence instead of 0.019). The Ricker spectrum vanishes as k^2
  // at k = 0. The window spreads the incidence angle by about width / window = 0.25 rad.
  const Real width = 3, window = 12, margin = 6;
  const Vec2 d(std::sin(theta), -std::cos(theta));
  const Vec2 e(std::cos(theta), std::sin(theta));
  const Real halfNormal = 3 * width * std::cos(theta) + 3 * window * std::sin(theta);    // extent along y
  const Real halfTangent = 3 * width * std::sin(theta) + 3 * window * std::cos(theta);   // extent along x
  const Vec2 centre(std::ceil(halfTangent + margin), std::ceil(halfNormal + margin));
  // The last part of the pulse meets the face at tLast; the reflected S (the slowest) is then one
  // pulse length plus a margin away from it at tEnd.
  const Real phi = std::asin(cs * std::sin(theta) / cp);
  const Real tFirst = margin / (cp * std::cos(theta));
  const Real tLast = (centre[1] + halfNormal) / (cp * std::cos(theta));
  const Real tEnd = tLast + (3 * width * cs / cp + 4) / (cs * std::cos(phi));
  const Real top = std::max(centre[1] + halfNormal, cp * std::cos(theta) * (tEnd - tFirst) + 3 * width) + margin;
  const Real right = centre[0] + cp * std::sin(theta) * tEnd + halfTangent + margin;
  const Block<2> block(Vec2::Zero(), Vec2(std::ceil(right), std::ceil(top)), 1.0, 2, 1.0);
  VeryWeakSphOptions options;
  options.material = m;
  VeryWeakSph<2> vw = assembleVeryWeakSph(block.particles, block.neighbours, block.kernel, options);
  if (transmitting) {
    const SparseMatrix c = assembleTransmittingDamping(block.particles, block.neighbours, block.kernel,
                                                       vw.data.facets, m, faceBit(BoxFace::MinusY), lumping);
    vw.system.setDamping(c);
  }
  const Index n = block.particles.physicalCount();
  if (particleCount) *particleCount = n;
  Vector u0(2 * n), v0(2 * n);
  for (Index a = 0; a < n; ++a) {
    const Vec2 r = block.particles.position(a) - centre;
    const Real xi = d.dot(r), eta = e.dot(r);
    const Real q = xi / width;
    const Real envelope = std::exp(-q * q / 2 - eta * eta / (2 * window * window));
    // Ricker profile g = (1 - q^2) exp(-q^2/2): g' = q (q^2 - 3) exp(-q^2/2) / width.
    u0.segment<2>(2 * a) = (1 - q * q) * envelope * d;
    v0.segment<2>(2 * a) = -cp * q * (q * q - 3) / width * envelope * d;
  }
  return energyFraction(vw.system, u0, v0, tEnd);
}

}  // namespace

TEST(TransmittingAbsorption, ObliqueIncidencePlaneStrainAgainstLysmerKuhlemeyer) {
  // Measured E(t_end) / E(0) with the -y face free, with Particle and with Consistent dashpots
  // (deterministic: the matrices are thread-count independent).
  struct Row {
    Real degrees, free, particle, consistent;
  };
  const Row measured[] = {{0, 0.98697, 0.01873, 0.01142},
                          {15, 0.92302, 0.01866, 0.01295},
                          {30, 0.75277, 0.01826, 0.01650},
                          {45, 0.55213, 0.03606, 0.03771},
                          {60, 0.43225, 0.12927, 0.13270}};
  const Material m = Material::fromLame(1, 1, 1);
  std::printf("theta  particles  free     particle  consistent  LK theory\n");
  for (const Row& row : measured) {
    const Real theta = row.degrees * M_PI / 180;
    Index count = 0;
    const Real free = obliqueReflectedFraction(theta, DashpotLumping::Particle, false, &count);
    const Real particle = obliqueReflectedFraction(theta, DashpotLumping::Particle, true, nullptr);
    const Real consistent = obliqueReflectedFraction(theta, DashpotLumping::Consistent, true, nullptr);
    const Real theory = lysmerKuhlemeyerReflection(m, theta).energy;
    std::printf("%5.1f  %9ld  %.5f  %.5f   %.5f     %.5f\n", row.degrees, static_cast<long>(count), free, particle,
                consistent, theory);
    EXPECT_NEAR(free, row.free, 1e-4);
    EXPECT_NEAR(particle, row.particle, 1e-4);
    EXPECT_NEAR(consistent, row.consistent, 1e-4);
    // Up to 45 degrees the published scheme is within 0.05 of the theory (worst measured: 0.035 at
    // 45 degrees); the floor of about 0.01-0.02 at small angles is the discrete dashpot's impedance
    // mismatch seen in 1-D (the dashpot acts on one or two rows only). At 60 degrees it sends back
    // 0.13 against 0.036: asserted as measured only.
    if (row.degrees <= 45) {
      EXPECT_NEAR(particle, theory, 0.05);
      EXPECT_NEAR(consistent, theory, 0.05);
    }
    // The free face should return all of it (theory: 1 at every angle) but the published scheme
    // keeps 0.99 at normal incidence and only 0.43 at 60 degrees: its free surface does not conserve
    // this energy (kinetic + 1/2 u^T K_sys u) at oblique incidence, where most of the energy turns into
    // short S waves (not investigated further here). Against it the dashpots absorb most of the pulse.
    EXPECT_LT(particle, 0.35 * free);
  }
}
