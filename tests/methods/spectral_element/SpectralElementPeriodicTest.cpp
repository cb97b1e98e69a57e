// lib/methods/spectral_element/SpectralElementElasticity with periodic faces (the plane-wave study's
// box): the node count and the mass of the periodic mesh, translations annihilated, K symmetric, a
// sampled plane P or S wave's Rayleigh quotient c^2 k^2 to an error that falls as the element
// size to the power 2N, the product bitwise the same on 1 and 2 threads, and bad input refused.

#include "core/Error.hpp"
#include "methods/spectral_element/SpectralElementElasticity.hpp"
#include "support/OnThreads.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace mfwave {
namespace {

template <int D>
SpectralElementSettings<D> periodicBox(int order, Real elementSize) {
  SpectralElementSettings<D> s;
  s.lower = Vec<D>::Zero();
  s.upper = Vec<D>::Ones();
  s.elementSize = elementSize;
  s.order = order;
  s.material = Material::fromLame(2.0, 1.5, 1.3);
  s.faces = SpectralElementSettings<D>::uniformFaces(SpectralElementFace::Periodic);
  return s;
}

// |u'K u / (omega^2 u'M u) - 1| for the sampled plane wave u along x (P: displacement along x, S:
// along y), omega = c k: the Rayleigh quotient's error, which is the interpolant's energy error
// squared, O((k h)^(2N)) (the sampled wave itself is no eigenvector: within an element the discrete
// mode's amplitude varies from node to node).
template <int D>
Real planeWaveFrequencyError(const SpectralElementElasticity<D>& system, bool shear, int wavelengths) {
  const Material& m = system.settings().material;
  const Real k = 2 * kPi * wavelengths, c = shear ? m.sWaveSpeed() : m.pWaveSpeed();
  Vector u = Vector::Zero(system.size());
  for (Index p = 0; p < system.nodeCount(); ++p) u[D * p + (shear ? 1 : 0)] = std::cos(k * system.nodePosition(p)[0]);
  Vector ku;
  system.applyStiffness(u, ku);
  const Real quotient = u.dot(ku) / u.dot(system.lumpedMass().cwiseProduct(u));
  return std::abs(quotient / ((c * k) * (c * k)) - 1);
}

TEST(SpectralElementPeriodic, NodesMassAndRigidTranslations) {
  const SpectralElementElasticity<2> system(periodicBox<2>(4, 0.25));
  EXPECT_EQ(system.nodeCount(), 16 * 16);  // 4 elements x N = 4 per axis, no closing line
  EXPECT_NEAR(system.lumpedMass().sum(), 2 * 1.3, 1e-12);  // D components x rho x area
  // No node on a face: a periodic box has none.
  const ParticleSet<2> particles = system.nodeParticles();
  for (Index i = 0; i < particles.size(); ++i) EXPECT_EQ(particles.faceMask[static_cast<std::size_t>(i)], 0);
  for (int c = 0; c < 2; ++c) {
    Vector shift = Vector::Zero(system.size());
    for (Index p = 0; p < system.nodeCount(); ++p) shift[2 * p + c] = 1;
    Vector k;
    system.applyStiffness(shift, k);
    EXPECT_LE(k.cwiseAbs().maxCoeff(), 1e-12) << "component " << c;
  }
}

TEST(SpectralElementPeriodic, StiffnessIsSymmetric) {
  const SpectralElementElasticity<2> system(periodicBox<2>(3, 0.5));
  const Index n = system.size();
  Eigen::MatrixXd k(n, n);
  Vector unit = Vector::Zero(n), column;
  for (Index j = 0; j < n; ++j) {
    unit[j] = 1;
    system.applyStiffness(unit, column);
    k.col(j) = column;
    unit[j] = 0;
  }
  EXPECT_LE((k - k.transpose()).cwiseAbs().maxCoeff(), 1e-12 * k.cwiseAbs().maxCoeff());
  // the wrap couples the first and last lines along x: node (0, 0) and the last node of row 0 (the
  // last element's far line is x = 0 again)
  const Index first = 0, last = system.nodesPerAxis()[0] - 1;
  EXPECT_GT(std::abs(k(2 * first, 2 * last)), 1e-3 * k.cwiseAbs().maxCoeff());
}

TEST(SpectralElementPeriodic, PlaneWaveFrequenciesConvergeAtOrderTwoN) {
  // N = 4, one wavelength across: halving the elements from 1/2 to 1/4 divides the Rayleigh
  // quotient's error by about 2^(2N) = 256.
  for (const bool shear : {false, true}) {
    const Real coarse = planeWaveFrequencyError(SpectralElementElasticity<2>(periodicBox<2>(4, 0.5)), shear, 1);
    const Real fine = planeWaveFrequencyError(SpectralElementElasticity<2>(periodicBox<2>(4, 0.25)), shear, 1);
    EXPECT_LT(fine, 1e-6) << (shear ? "S" : "P");
    EXPECT_GT(coarse / fine, 100) << (shear ? "S" : "P") << ": " << coarse << " -> " << fine;
  }
  EXPECT_LT(planeWaveFrequencyError(SpectralElementElasticity<3>(periodicBox<3>(4, 0.5)), false, 1), 0.02);
  EXPECT_LT(planeWaveFrequencyError(SpectralElementElasticity<3>(periodicBox<3>(4, 0.5)), true, 1), 0.02);
}

TEST(SpectralElementPeriodic, ProductIsBitwiseTheSameOnOneAndTwoThreads) {
  // 8^3 = 512 elements: above the one-thread threshold
  const SpectralElementElasticity<3> system(periodicBox<3>(2, 0.125));
  Vector x(system.size());
  for (Index i = 0; i < x.size(); ++i) x[i] = std::sin(0.37 * static_cast<Real>(i)) + 0.1 * std::cos(1.3 * i);
  const auto product = [&] {
    Vector y;
    system.applyStiffness(x, y);
    return y;
  };
  const Vector one = testing::onThreads(1, product), two = testing::onThreads(2, product);
  EXPECT_EQ(std::memcmp(one.data(), two.data(), sizeof(Real) * static_cast<std::size_t>(one.size())), 0);
}

TEST(SpectralElementPeriodic, RefusesBadInput) {
  SpectralElementSettings<2> oneSided = periodicBox<2>(4, 0.25);
  oneSided.faces[1] = SpectralElementFace::Free;
  EXPECT_THROW(SpectralElementElasticity<2>{oneSided}, InputError);
  // three elements around a periodic axis: the first and last would share a parity colour
  EXPECT_THROW(SpectralElementElasticity<2>{periodicBox<2>(4, 1.0 / 3)}, InputError);
  SpectralElementSettings<2> loaded = periodicBox<2>(4, 0.25);
  SpectralElementTraction<2> t;
  t.face = 3;
  t.centre = Vec2(0.5, 1);
  t.halfWidth = Vec2(0.1, 0);
  t.traction = Vec2(0, 1);
  t.history = [](Real) { return 1.0; };
  loaded.tractions.push_back(t);
  EXPECT_THROW(SpectralElementElasticity<2>{loaded}, InputError);
  // one element around an axis is allowed (its two faces are one)
  EXPECT_NO_THROW(SpectralElementElasticity<2>{periodicBox<2>(4, 1.0)});
}

}  // namespace
}  // namespace mfwave
