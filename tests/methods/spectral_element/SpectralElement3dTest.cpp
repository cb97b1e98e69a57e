// lib/methods/spectral_element/SpectralElementElasticity in 3-D, and its sum-factorised product in
// both dimensions: the product equals the dense element matrix built the slow way (B^T D B at every
// GLL point); K annihilates the six rigid motions and is symmetric; a uniform strain leaves exactly
// the face tractions' work-equivalent forces; central difference on free faces keeps its energy; the
// exact axial mode's frequency converges at order about 2N; the product is the same, bit for bit,
// on one and two threads (the elements run in colours that share no node).

#include "methods/spectral_element/GaussLobattoLegendre.hpp"
#include "methods/spectral_element/SpectralElementElasticity.hpp"
#include "support/OnThreads.hpp"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

namespace mfwave {
namespace {

template <int D>
SpectralElementSettings<D> cube(int order, Real elementSize, Vec<D> lower, Vec<D> upper) {
  SpectralElementSettings<D> s;
  s.lower = lower;
  s.upper = upper;
  s.elementSize = elementSize;
  s.order = order;
  s.material = Material::fromLame(2.0, 1.5, 1.3);
  return s;
}

// The dense element matrix the slow way (Komatitsch & Tromp 1999, eq. 19 ff.): with g_l the
// gradient of phi_l at a GLL point, entry (l, c), (m, d) gains w J (lambda g_l[c] g_m[d] +
// mu (g_l[d] g_m[c] + delta_cd g_l . g_m)).
template <int D>
Eigen::MatrixXd denseElementMatrix(int order, Real h, const Material& material) {
  const int points = order + 1;
  int count = 1;
  for (int d = 0; d < D; ++d) count *= points;
  const QuadratureRule rule = gaussLobattoLegendre(order);
  const Eigen::MatrixXd dm = lagrangeDerivativeMatrix(rule.nodes);
  const auto digit = [points](int index, int axis) {
    for (int d = 0; d < axis; ++d) index /= points;
    return index % points;
  };
  const Real lambda = material.lambda(), mu = material.mu();
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(D * count, D * count);
  Eigen::MatrixXd g(count, D);
  for (int q = 0; q < count; ++q) {
    Real weight = std::pow(0.5 * h, D);
    for (int d = 0; d < D; ++d) weight *= rule.weights[static_cast<std::size_t>(digit(q, d))];
    for (int l = 0; l < count; ++l)
      for (int d = 0; d < D; ++d) {
        bool onLine = true;
        for (int e = 0; e < D; ++e)
          if (e != d && digit(l, e) != digit(q, e)) onLine = false;
        g(l, d) = onLine ? 2 / h * dm(digit(q, d), digit(l, d)) : 0.0;
      }
    for (int l = 0; l < count; ++l)
      for (int m = 0; m < count; ++m) {
        const Real dot = g.row(l).dot(g.row(m));
        for (int c = 0; c < D; ++c)
          for (int d = 0; d < D; ++d)
            k(D * l + c, D * m + d) +=
                weight * (lambda * g(l, c) * g(m, d) + mu * (g(l, d) * g(m, c) + (c == d ? dot : 0.0)));
      }
  }
  return k;
}

TEST(SpectralElement3d, SumFactorisationEqualsTheDenseElementMatrix) {
  for (int order = 1; order <= 6; ++order) {
    const SpectralElementElasticity<2> plane(cube<2>(order, 0.5, Vec2(0, 0), Vec2(0.5, 0.5)));
    const Eigen::MatrixXd k2 = denseElementMatrix<2>(order, 0.5, plane.settings().material);
    EXPECT_LE((plane.elementStiffness() - k2).cwiseAbs().maxCoeff(), 1e-12 * k2.cwiseAbs().maxCoeff()) << order;
    const SpectralElementElasticity<3> solid(cube<3>(order, 0.5, Vec3(0, 0, 0), Vec3(0.5, 0.5, 0.5)));
    const Eigen::MatrixXd k3 = denseElementMatrix<3>(order, 0.5, solid.settings().material);
    EXPECT_LE((solid.elementStiffness() - k3).cwiseAbs().maxCoeff(), 1e-12 * k3.cwiseAbs().maxCoeff()) << order;
  }
}

TEST(SpectralElement3d, AnnihilatesTheSixRigidMotionsAndIsSymmetric) {
  for (int order : {1, 2, 4}) {
    SpectralElementSettings<3> s = cube<3>(order, 0.5, Vec3(-0.5, 0, -1), Vec3(0.5, 0.5, 0));
    const SpectralElementElasticity<3> system(s);
    const Eigen::MatrixXd k = system.elementStiffness();
    const Real scale = k.cwiseAbs().maxCoeff();
    EXPECT_LE((k - k.transpose()).cwiseAbs().maxCoeff(), 1e-13 * scale) << order;
    const Index n = system.nodeCount();
    for (int mode = 0; mode < 6; ++mode) {
      Vector u(3 * n), ku;
      for (Index p = 0; p < n; ++p) {
        const Vec3 x = system.nodePosition(p);
        Vec3 value = Vec3::Zero();
        if (mode < 3) value[mode] = 1;
        else value = Vec3::Unit(mode - 3).cross(x);  // infinitesimal rotation about an axis
        u.segment<3>(3 * p) = value;
      }
      system.applyStiffness(u, ku);
      EXPECT_LE(ku.cwiseAbs().maxCoeff(), 1e-12 * scale) << "order " << order << " mode " << mode;
    }
    // exactly six zero eigenvalues of one element (no spurious zero-energy modes)
    if (order <= 2) {
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(0.5 * (k + k.transpose()), Eigen::EigenvaluesOnly);
      int zeros = 0;
      for (Index i = 0; i < eigen.eigenvalues().size(); ++i) {
        EXPECT_GT(eigen.eigenvalues()[i], -1e-12 * scale);
        if (std::abs(eigen.eigenvalues()[i]) < 1e-10 * scale) ++zeros;
      }
      EXPECT_EQ(zeros, 6) << order;
    }
    // the assembled K with fixed and absorbing faces: x^T K y = y^T K x
    s.faces[0] = SpectralElementFace::Fixed;
    s.faces[4] = SpectralElementFace::Absorbing;
    const SpectralElementElasticity<3> masked(s);
    const Vector x = Vector::Random(masked.size()), y = Vector::Random(masked.size());
    Vector kx, ky;
    masked.applyStiffness(x, kx);
    masked.applyStiffness(y, ky);
    EXPECT_NEAR(y.dot(kx), x.dot(ky), 1e-12 * std::abs(y.dot(kx))) << order;
    for (Index dof = 0; dof < masked.size(); ++dof)
      if (masked.fixedDofs()[static_cast<std::size_t>(dof)]) {
        EXPECT_EQ(kx[dof], 0);
      }
    // the Gershgorin row sums bound the diagonal
    const Vector sums = masked.stiffnessAbsoluteRowSums();
    Vector unit = Vector::Zero(masked.size()), column;
    for (Index j = 0; j < masked.size(); j += 11) {
      unit.setZero();
      unit[j] = 1;
      masked.applyStiffness(unit, column);
      EXPECT_LE(column.cwiseAbs().sum(), sums[j] + 1e-12 * scale);
    }
  }
}

// u = G x: K u is the work-equivalent of the traction sigma n on every face, which the system's own
// exact face loads compute; interior forces vanish and each face's forces sum to sigma n A.
TEST(SpectralElement3d, UniformStrainLeavesOnlyTheFaceTractions) {
  Mat3 g;
  g << 0.3, -0.2, 0.1, 0.5, 0.1, -0.4, 0.2, 0.3, -0.1;
  for (int order : {1, 2, 4}) {
    SpectralElementSettings<3> s = cube<3>(order, 0.5, Vec3(-1, -0.5, -1), Vec3(0.5, 0.5, 0));
    const Real lambda = s.material.lambda(), mu = s.material.mu();
    const Mat3 strain = 0.5 * (g + g.transpose());
    const Mat3 stress = lambda * strain.trace() * Mat3::Identity() + 2 * mu * strain;
    for (int face = 0; face < 6; ++face) {
      SpectralElementTraction<3> t;
      t.face = face;
      t.centre = 0.5 * (s.lower + s.upper);
      t.halfWidth = 0.5 * (s.upper - s.lower);
      t.traction = stress * Vec3::Unit(face / 2) * (face % 2 == 0 ? -1.0 : 1.0);
      t.history = [](Real) { return 1.0; };
      s.tractions.push_back(t);
    }
    const SpectralElementElasticity<3> system(s);
    const Index n = system.nodeCount();
    Vector u(3 * n), ku, f;
    for (Index p = 0; p < n; ++p) u.segment<3>(3 * p) = g * system.nodePosition(p);
    system.applyStiffness(u, ku);
    system.force(0, f);
    EXPECT_LE((ku - f).cwiseAbs().maxCoeff(), 1e-12) << order;
    const ParticleSet<3> nodes = system.nodeParticles();
    Vec3 plusX = Vec3::Zero();
    for (Index p = 0; p < n; ++p) {
      const std::uint8_t faces = nodes.faceMask[static_cast<std::size_t>(p)];
      if (faces == 0) {
        EXPECT_LE(ku.segment<3>(3 * p).cwiseAbs().maxCoeff(), 1e-12) << order;
      }
    }
    // the +x face's share alone: its traction's load vector sums to sigma e_x times its area
    SpectralElementSettings<3> one = s;
    one.tractions = {s.tractions[1]};
    const SpectralElementElasticity<3> loaded(one);
    loaded.force(0, f);
    for (Index p = 0; p < n; ++p) plusX += f.segment<3>(3 * p);
    EXPECT_LE((plusX - stress * Vec3::UnitX() * 1.0 * 1.0).cwiseAbs().maxCoeff(), 1e-12) << order;
  }
}

TEST(SpectralElement3d, MassDashpotsAndSquareLoadIntegrateWhatTheyShould) {
  SpectralElementSettings<3> s = cube<3>(3, 1.0, Vec3(-2, -1, -2), Vec3(2, 2, 0));
  s.faces = SpectralElementSettings<3>::uniformFaces(SpectralElementFace::Absorbing);
  s.faces[5] = SpectralElementFace::Free;
  SpectralElementTraction<3> load;
  load.face = 5;
  load.centre = Vec3(0.1, 0.2, 0);
  load.halfWidth = Vec3(0.55, 0.3, 0);  // edges inside elements
  load.traction = Vec3(0.25, 0, -1);
  load.history = [](Real t) { return 2 * t; };
  s.tractions.push_back(load);
  const SpectralElementElasticity<3> system(s);
  const Vector m = system.lumpedMass();
  const Real rho = s.material.density(), volume = 4 * 3 * 2;
  EXPECT_NEAR(m.sum(), 3 * rho * volume, 1e-11);
  const Real cp = s.material.pWaveSpeed(), cs = s.material.sWaveSpeed();
  Vec3 c = Vec3::Zero();
  for (Index p = 0; p < system.nodeCount(); ++p) c += system.dampingDiagonal().segment<3>(3 * p);
  // faces: +-x area 6 each, +-y area 8 each, -z area 12
  EXPECT_NEAR(c[0], rho * (cp * 12 + cs * 16 + cs * 12), 1e-11);
  EXPECT_NEAR(c[1], rho * (cs * 12 + cp * 16 + cs * 12), 1e-11);
  EXPECT_NEAR(c[2], rho * (cs * 12 + cs * 16 + cp * 12), 1e-11);
  Vector f;
  system.force(0.75, f);
  Vec3 total = Vec3::Zero();
  Real momentX = 0, momentY = 0;
  for (Index p = 0; p < system.nodeCount(); ++p) {
    total += f.segment<3>(3 * p);
    momentX += f[3 * p + 2] * system.nodePosition(p)[0];
    momentY += f[3 * p + 2] * system.nodePosition(p)[1];
    if (f.segment<3>(3 * p).squaredNorm() > 0) {
      EXPECT_NEAR(system.nodePosition(p)[2], 0, 1e-15);
    }
  }
  const Real area = 1.1 * 0.6;
  EXPECT_NEAR(total[0], 0.25 * area * 1.5, 1e-13);
  EXPECT_NEAR(total[2], -area * 1.5, 1e-13);
  EXPECT_NEAR(momentX, -area * 1.5 * 0.1, 1e-13);  // first moments: the exact centroid
  EXPECT_NEAR(momentY, -area * 1.5 * 0.2, 1e-13);
  EXPECT_GE(system.nodeAt(Vec3(0, 0, 0)), 0);
  EXPECT_EQ(system.nodeAt(Vec3(0.1, 0, 0)), -1);
  EXPECT_NEAR((system.nodePosition(system.nodeAt(Vec3(2, -1, -1))) - Vec3(2, -1, -1)).norm(), 0, 1e-15);
}

TEST(SpectralElement3d, CentralDifferenceConservesEnergyOnFreeFaces) {
  SpectralElementSettings<3> s = cube<3>(3, 0.5, Vec3(0, 0, 0), Vec3(1, 0.5, 0.5));
  SpectralElementElasticity<3> system(s);
  const Vector m = system.lumpedMass();
  // the step: half the power-iteration limit
  Vector x(system.size()), kx;
  for (Index i = 0; i < x.size(); ++i) x[i] = std::sin(0.37 * static_cast<Real>(i) + 0.1);
  Real omega2 = 0;
  for (int k = 0; k < 500; ++k) {
    system.applyStiffness(x, kx);
    const Vector y = kx.cwiseQuotient(m);
    omega2 = y.norm() / x.norm();
    x = y / y.norm();
  }
  const Real dt = 0.5 * 2 / std::sqrt(omega2);
  Vector u(system.size()), a(system.size());
  for (Index p = 0; p < system.nodeCount(); ++p) {
    const Vec3 y = system.nodePosition(p);
    u.segment<3>(3 * p) = 0.01 * Vec3(std::sin(1.3 * y[0]) * std::cos(2.1 * y[1]), std::cos(0.7 * y[0] + y[2]),
                                      y[1] * y[2]);
  }
  system.acceleration(0, u, Vector::Zero(system.size()), a);
  Vector vHalf = 0.5 * dt * a, ku;
  Real reference = -1, drift = 0;
  for (int k = 0; k < 2000; ++k) {
    const Vector uNext = u + dt * vHalf;
    system.applyStiffness(uNext, ku);
    const Real conserved = system.kineticEnergy(vHalf) + 0.5 * u.dot(ku);
    if (reference < 0) reference = conserved;
    drift = std::max(drift, std::abs(conserved - reference) / reference);
    system.acceleration(0, uNext, vHalf, a);
    vHalf += dt * a;
    u = uNext;
  }
  EXPECT_LT(drift, 1e-9);
}

// The lowest axial mode of [0, 4] x [0, 1]^2 with lambda = 0, the x faces fixed, the others free:
// u = (sin(pi x / 4), 0, 0) is exact, omega = pi c_p / 4 with c_p = sqrt(2 mu / rho). The fields
// (f(x), 0, 0) with f in the SEM space along x are invariant under M^-1 K (lambda = 0 couples no
// other component), so the 3-D operator's frequency comes from its restriction to them, which the
// test checks before using it.
Real axialModeError3d(int order, Real elementSize) {
  SpectralElementSettings<3> s;
  s.lower = Vec3(0, 0, 0);
  s.upper = Vec3(4, 1, 1);
  s.elementSize = elementSize;
  s.order = order;
  s.material = Material::fromLame(0, 1, 1);
  s.faces[0] = s.faces[1] = SpectralElementFace::Fixed;
  const SpectralElementElasticity<3> system(s);
  const Index nx = system.nodesPerAxis()[0];
  const Index free = nx - 2;
  Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(system.size(), free);
  for (Index p = 0; p < system.nodeCount(); ++p) {
    const Index i = p % nx;
    if (i > 0 && i < nx - 1) basis(3 * p, i - 1) = 1;
  }
  Eigen::MatrixXd kb(system.size(), free);
  Vector column;
  for (Index j = 0; j < free; ++j) {
    system.applyStiffness(basis.col(j), column);
    kb.col(j) = column;
  }
  const Vector m = system.lumpedMass();
  const Eigen::MatrixXd kr = basis.transpose() * kb;
  const Vector mr = (basis.transpose() * m.asDiagonal() * basis).diagonal();
  // invariance: K B = M B (M_r^-1 K_r)
  const Eigen::MatrixXd image = m.asDiagonal() * basis * (mr.cwiseInverse().asDiagonal() * kr);
  EXPECT_LE((kb - image).cwiseAbs().maxCoeff(), 1e-10 * kb.cwiseAbs().maxCoeff());
  const Eigen::MatrixXd a = mr.cwiseSqrt().cwiseInverse().asDiagonal() * kr * mr.cwiseSqrt().cwiseInverse().asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(0.5 * (a + a.transpose()), Eigen::EigenvaluesOnly);
  const Real exact = std::acos(-1.0) * std::sqrt(2.0) / 4;
  Real closest = std::numeric_limits<Real>::infinity();
  for (Index i = 0; i < eigen.eigenvalues().size(); ++i) {
    const Real omega = std::sqrt(std::max<Real>(eigen.eigenvalues()[i], 0));
    if (std::abs(omega - exact) < std::abs(closest - exact)) closest = omega;
  }
  return std::abs(closest - exact) / exact;
}

TEST(SpectralElement3d, AxialModeFrequencyConvergesAtOrderAbout2N) {
  for (int order : {1, 2, 3}) {
    const Real coarse = axialModeError3d(order, 1.0), fine = axialModeError3d(order, 0.5);
    const Real measured = std::log2(coarse / fine);
    std::printf("3-D N = %d: relative frequency errors %.3e (h = 1), %.3e (h = 0.5), order %.2f\n", order, coarse,
                fine, measured);
    EXPECT_GE(measured, 2 * order - 0.5) << "order " << order;
  }
}

// Not a check: the speed of the sum-factorised product against the dense element matrix on the same
// 3-D mesh (node-products per second), printed for the record.
TEST(SpectralElement3d, SumFactorisationIsFasterThanTheDenseElementMatrix) {
  const SpectralElementElasticity<3> system(cube<3>(4, 0.5, Vec3(0, 0, 0), Vec3(2, 2, 2)));
  const Eigen::MatrixXd k = system.elementStiffness();
  const Vector x = Vector::Random(system.size());
  Vector y;
  using Clock = std::chrono::steady_clock;
  const int repeats = 30;
  const auto t0 = Clock::now();
  for (int r = 0; r < repeats; ++r) system.applyStiffness(x, y);
  const Real fast = std::chrono::duration<Real>(Clock::now() - t0).count() / repeats;
  // the dense product element by element (gather, K_e x_e, scatter), as the 2-D code did before
  const auto t1 = Clock::now();
  Vector dense = Vector::Zero(system.size()), local(k.rows()), product(k.rows());
  const Index n = system.settings().order, nx = system.nodesPerAxis()[0], ny = system.nodesPerAxis()[1];
  const Index points = n + 1;
  for (Index ez = 0; ez < system.elementsPerAxis()[2]; ++ez)
    for (Index ey = 0; ey < system.elementsPerAxis()[1]; ++ey)
      for (Index ex = 0; ex < system.elementsPerAxis()[0]; ++ex) {
        for (Index l = 0; l < points * points * points; ++l) {
          const Index node = ((ez * n + l / (points * points)) * ny + ey * n + (l / points) % points) * nx + ex * n +
                             l % points;
          local.segment<3>(3 * l) = x.segment<3>(3 * node);
        }
        product.noalias() = k * local;
        for (Index l = 0; l < points * points * points; ++l) {
          const Index node = ((ez * n + l / (points * points)) * ny + ey * n + (l / points) % points) * nx + ex * n +
                             l % points;
          dense.segment<3>(3 * node) += product.segment<3>(3 * l);
        }
      }
  const Real slow = std::chrono::duration<Real>(Clock::now() - t1).count();
  EXPECT_LE((dense - y).cwiseAbs().maxCoeff(), 1e-12 * y.cwiseAbs().maxCoeff());
  const auto nodes = static_cast<Real>(system.nodeCount());
  std::printf("3-D N = 4, %lld nodes: sum factorisation %.3g node-products/s, dense element matrix %.3g\n",
              static_cast<long long>(system.nodeCount()), nodes / fast, nodes / slow);
}

// The same in 2-D, element by element (gather, product, scatter): the plane-strain element matrix is
// small (50 square for N = 4) and its vectorised dense product the faster one, which is why the 2-D
// system keeps it (assembled from the sum-factorised product); printed for the record.
TEST(SpectralElement3d, SumFactorisationAgainstTheDenseElementMatrixIn2d) {
  const SpectralElementElasticity<2> system(cube<2>(4, 0.5, Vec2(0, 0), Vec2(8, 8)));
  const Eigen::MatrixXd k = system.elementStiffness();
  const Vector x = Vector::Random(system.size());
  const Index n = system.settings().order, nx = system.nodesPerAxis()[0], points = n + 1;
  using Clock = std::chrono::steady_clock;
  const int repeats = 30;
  Vector local(k.rows()), product(k.rows());
  std::array<Vector, 2> results;
  std::array<Real, 2> seconds{};
  for (int way = 0; way < 2; ++way) {
    const auto t0 = Clock::now();
    for (int r = 0; r < repeats; ++r) {
      Vector& y = results[static_cast<std::size_t>(way)];
      y = Vector::Zero(system.size());
      for (Index ey = 0; ey < system.elementsPerAxis()[1]; ++ey)
        for (Index ex = 0; ex < system.elementsPerAxis()[0]; ++ex) {
          for (Index l = 0; l < points * points; ++l)
            local.segment<2>(2 * l) = x.segment<2>(2 * ((ey * n + l / points) * nx + ex * n + l % points));
          if (way == 0) system.elementProduct(local.data(), product.data());
          else product.noalias() = k * local;
          for (Index l = 0; l < points * points; ++l)
            y.segment<2>(2 * ((ey * n + l / points) * nx + ex * n + l % points)) += product.segment<2>(2 * l);
        }
    }
    seconds[static_cast<std::size_t>(way)] = std::chrono::duration<Real>(Clock::now() - t0).count() / repeats;
  }
  EXPECT_LE((results[0] - results[1]).cwiseAbs().maxCoeff(), 1e-12 * results[1].cwiseAbs().maxCoeff());
  const auto nodes = static_cast<Real>(system.nodeCount());
  std::printf("2-D N = 4, %lld nodes: sum factorisation %.3g node-products/s, dense element matrix %.3g\n",
              static_cast<long long>(system.nodeCount()), nodes / seconds[0], nodes / seconds[1]);
}

// Enough elements for the parallel product (kParallelElements = 64), in 2-D (the cached dense K_e)
// and in 3-D (sum factorisation), with fixed and absorbing faces present: bitwise the same K u on 1
// and 2 threads.
template <int D>
void expectThreadIndependentProduct(const Vec<D>& upper) {
  SpectralElementSettings<D> s = cube<D>(3, 1.0, Vec<D>::Zero(), upper);
  s.faces[0] = SpectralElementFace::Fixed;
  s.faces[1] = SpectralElementFace::Absorbing;
  const SpectralElementElasticity<D> system(s);
  ASSERT_GE(system.elementCount(), 64);
  Vector x(system.size());
  for (Index i = 0; i < x.size(); ++i) x[i] = std::sin(0.37 * static_cast<Real>(i) + 0.1);
  const auto product = [&] {
    Vector y;
    system.applyStiffness(x, y);
    return y;
  };
  const Vector serial = testing::onThreads(1, product), parallel = testing::onThreads(2, product);
  ASSERT_EQ(serial.size(), parallel.size());
  for (Index i = 0; i < serial.size(); ++i) ASSERT_EQ(serial[i], parallel[i]) << "unknown " << i;
  EXPECT_GT(serial.norm(), 0);
}

TEST(SpectralElementElasticity, ProductIsBitwiseTheSameOnOneAndTwoThreads) {
  expectThreadIndependentProduct<2>(Vec<2>(10.0, 8.0));
  expectThreadIndependentProduct<3>(Vec<3>(5.0, 4.0, 4.0));
}

}  // namespace
}  // namespace mfwave
