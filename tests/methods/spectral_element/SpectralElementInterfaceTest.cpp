// Materials by region in the spectral elements (issue 48): a plane P pulse at normal incidence on the
// interface between two materials of impedance ratio Z2 / Z1 = 3 (and wave-speed ratio 2) splits
// into a reflected pulse of displacement amplitude (Z1 - Z2) / (Z1 + Z2) = -1/2 and a transmitted one
// of 2 Z1 / (Z1 + Z2) = 1/2, stretched by c2 / c1. Measured on a box periodic across the pulse (a
// 1-D problem in a 2-D and a 3-D mesh, the 3-D one with a narrower pulse in a shorter box), each
// amplitude fitted to the exact shape, within 1 % of the
// exact coefficient, the shapes within 2 %, and the energy conserved. One material in both layers
// reflects nothing, and an element no region covers is refused by name.

#include "core/Error.hpp"
#include "methods/spectral_element/SpectralElementElasticity.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace mfwave {
namespace {

// The incident pulse's shape: a smooth bump of half-width w (C^3 at its ends).
Real bump(Real s, Real w) {
  const Real r = s / w;
  return std::abs(r) < 1 ? std::pow(1 - r * r, 4) : 0.0;
}
Real bumpSlope(Real s, Real w) {
  const Real r = s / w;
  return std::abs(r) < 1 ? -8 * r / w * std::pow(1 - r * r, 3) : 0.0;
}

// The box along y (interface at y = 0) and the pulse: its start and half-width. The 3-D case runs a
// pulse half as wide in a box half as tall (a quarter of the work; the same code path).
struct Layout {
  Real top, bottom, start, halfWidth;
};
constexpr Layout kWide{6, -10, 4, 1}, kNarrow{3, -5, 2, 0.5};

template <int D>
SpectralElementSettings<D> layeredBox(const Material& upper, const Material& lower, const Layout& layout = kWide) {
  SpectralElementSettings<D> s;
  s.elementSize = 0.25;
  s.order = 4;
  s.lower = Vec<D>::Zero();
  s.upper = Vec<D>::Constant(0.5);  // two elements across, periodic
  s.lower[1] = layout.bottom;
  s.upper[1] = layout.top;
  s.faces = SpectralElementSettings<D>::uniformFaces(SpectralElementFace::Periodic);
  s.faces[2] = s.faces[3] = SpectralElementFace::Free;
  s.regionMaterials = {upper, lower};
  s.materialAt = [](const Vec<D>& centre) { return centre[1] > 0 ? 0 : 1; };
  return s;
}

struct Split {
  Real reflected = 0, transmitted = 0;  // fitted amplitudes
  Real reflectedShape = 0, transmittedShape = 0;  // |u - A g| / |A g| on each side
  Real energyDrift = 0;
};

// The pulse u_y = g(y - y0 + c1 t) coming down through the upper material, stepped by central
// differences to t = 2 y0 / c1, when the exact reflected pulse is R g(y0 - y) and the transmitted
// one T g(y c1 / c2 + y0).
template <int D>
Split splitPulse(const Material& upper, const Material& lower, const Layout& layout = kWide) {
  SpectralElementElasticity<D> system(layeredBox<D>(upper, lower, layout));
  const Real kStart = layout.start, kHalfWidth = layout.halfWidth;
  const Real c1 = upper.pWaveSpeed(), c2 = lower.pWaveSpeed();
  const Index n = system.nodeCount();
  const Real end = 2 * kStart / c1, dt = 0.002;
  const auto steps = static_cast<Index>(std::ceil(end / dt));
  const Real step = end / static_cast<Real>(steps);
  Vector u = Vector::Zero(system.size()), previous = Vector::Zero(system.size()), v = Vector::Zero(system.size());
  for (Index p = 0; p < n; ++p) {
    const Real y = system.nodePosition(p)[1];
    u[D * p + 1] = bump(y - kStart, kHalfWidth);
    previous[D * p + 1] = bump(y - kStart - c1 * step, kHalfWidth);
    v[D * p + 1] = c1 * bumpSlope(y - kStart, kHalfWidth);
  }
  Vector ku;
  system.applyStiffness(u, ku);
  const Real energy0 = system.kineticEnergy(v) + 0.5 * u.dot(ku);
  Vector a(system.size()), next(system.size());
  for (Index k = 0; k < steps; ++k) {
    system.acceleration(k * step, u, v, a);
    next = 2 * u - previous + step * step * a;
    previous.swap(u);
    u.swap(next);
  }
  // energy at the last step: velocity centred on it, strain of the mean of the two displacements'
  // product (the central-difference invariant up to O(dt^2))
  v = (u - previous) / step;
  system.applyStiffness(u, ku);
  Vector kPrevious;
  system.applyStiffness(previous, kPrevious);
  const Real energy = system.kineticEnergy(v) + 0.25 * (u.dot(ku) + previous.dot(kPrevious));

  // least-squares amplitude against the exact shape, with the nodal quadrature (the nodes' volumes)
  const ParticleSet<D> nodes = system.nodeParticles();
  Real rg = 0, gg = 0, tg = 0, hh = 0, rr = 0, tt = 0;
  for (Index p = 0; p < n; ++p) {
    const Real y = system.nodePosition(p)[1], w = nodes.volume[static_cast<std::size_t>(p)];
    const Real uy = u[D * p + 1];
    if (y > 0) {
      const Real g = bump(kStart - y, kHalfWidth);
      rg += w * uy * g;
      gg += w * g * g;
      rr += w * uy * uy;
    } else if (y < 0) {
      const Real g = bump(y * c1 / c2 + kStart, kHalfWidth);
      tg += w * uy * g;
      hh += w * g * g;
      tt += w * uy * uy;
    }
  }
  Split out;
  out.reflected = rg / gg;
  out.transmitted = tg / hh;
  // |u - A g|^2 = |u|^2 - A^2 |g|^2 for the least-squares A
  out.reflectedShape = std::sqrt(std::max<Real>(0, rr - out.reflected * out.reflected * gg)) /
                       std::max<Real>(std::abs(out.reflected) * std::sqrt(gg), 1e-300);
  out.transmittedShape = std::sqrt(std::max<Real>(0, tt - out.transmitted * out.transmitted * hh)) /
                         (std::abs(out.transmitted) * std::sqrt(hh));
  out.energyDrift = std::abs(energy / energy0 - 1);
  return out;
}

const Material kUpper = Material::fromLame(1.0, 1.0, 1.0);  // c_p = sqrt 3, Z1 = sqrt 3
const Material kLower = Material::fromLame(6.0, 6.0, 1.5);  // c_p = 2 sqrt 3, Z2 = 3 sqrt 3

template <int D>
void expectImpedanceRatioThree(const Layout& layout) {
  SCOPED_TRACE(std::to_string(D) + "-D");
  const Real z1 = kUpper.density() * kUpper.pWaveSpeed(), z2 = kLower.density() * kLower.pWaveSpeed();
  ASSERT_NEAR(z2 / z1, 3.0, 1e-12);
  const Real reflection = (z1 - z2) / (z1 + z2), transmission = 2 * z1 / (z1 + z2);
  const Split split = splitPulse<D>(kUpper, kLower, layout);
  std::printf("%d-D: reflected %.5f (exact %.5f), transmitted %.5f (exact %.5f), shape misfit %.2e / %.2e, energy drift %.1e\n",
              D, split.reflected, reflection, split.transmitted, transmission, split.reflectedShape,
              split.transmittedShape, split.energyDrift);
  EXPECT_NEAR(split.reflected / reflection, 1.0, 0.01) << "reflected " << split.reflected << ", exact " << reflection;
  EXPECT_NEAR(split.transmitted / transmission, 1.0, 0.01)
      << "transmitted " << split.transmitted << ", exact " << transmission;
  EXPECT_LT(split.reflectedShape, 0.02);
  EXPECT_LT(split.transmittedShape, 0.02);
  EXPECT_LT(split.energyDrift, 1e-3);
}

TEST(SpectralElementInterface, ImpedanceRatioThreeIn2d) { expectImpedanceRatioThree<2>(kWide); }

TEST(SpectralElementInterface, ImpedanceRatioThreeIn3d) { expectImpedanceRatioThree<3>(kNarrow); }

TEST(SpectralElementInterface, OneMaterialReflectsNothing) {
  const Split split = splitPulse<2>(kUpper, kUpper);
  EXPECT_LT(std::abs(split.reflected), 1e-3);
  EXPECT_NEAR(split.transmitted, 1.0, 1e-3);
}

TEST(SpectralElementInterface, ElementWithoutMaterialIsRefused) {
  SpectralElementSettings<2> s = layeredBox<2>(kUpper, kLower);
  s.materialAt = [](const Vec<2>& centre) { return centre[1] > -5 ? 0 : -1; };
  try {
    SpectralElementElasticity<2> system(s);
    FAIL() << "an element below y = -5 has no material";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "material");
    EXPECT_NE(std::string(e.what()).find("no region"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mfwave
