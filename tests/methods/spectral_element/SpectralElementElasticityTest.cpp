// lib/methods/spectral_element/SpectralElementElasticity, its operators at rest: the element
// stiffness is symmetric and annihilates rigid-body motions; a uniform strain on a free mesh leaves
// residual forces on the boundary only, whose sum over a face is the face's traction; the lumped
// mass, the dashpots and the strip load integrate what they should; bad input is refused.

#include "core/Error.hpp"
#include "methods/spectral_element/SpectralElementElasticity.hpp"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>

namespace mfwave {
namespace {

SpectralElementSettings<2> box(int order, Real elementSize, Vec2 lower = Vec2(-1, -1), Vec2 upper = Vec2(2, 1)) {
  SpectralElementSettings<2> s;
  s.lower = lower;
  s.upper = upper;
  s.elementSize = elementSize;
  s.order = order;
  s.material = Material::fromLame(2.0, 1.5, 1.3);
  return s;
}

TEST(SpectralElementElasticity, ElementStiffnessIsSymmetricAndAnnihilatesRigidMotions) {
  for (int order = 1; order <= 8; ++order) {
    const SpectralElementElasticity<2> system(box(order, 0.5, Vec2(0, 0), Vec2(0.5, 0.5)));
    const Eigen::MatrixXd& k = system.elementStiffness();
    const Real scale = k.cwiseAbs().maxCoeff();
    EXPECT_LE((k - k.transpose()).cwiseAbs().maxCoeff(), 1e-14 * scale) << "order " << order;
    // the single element's nodes are the global ones, so positions come from the system
    const Index n = system.nodeCount();
    ASSERT_EQ(2 * n, k.rows());
    Vector shiftX = Vector::Zero(2 * n), shiftY = Vector::Zero(2 * n), rotation(2 * n);
    for (Index p = 0; p < n; ++p) {
      const Vec2 x = system.nodePosition(p);
      shiftX[2 * p] = 1;
      shiftY[2 * p + 1] = 1;
      rotation[2 * p] = -x[1];
      rotation[2 * p + 1] = x[0];
    }
    for (const Vector* mode : {&shiftX, &shiftY, &rotation}) {
      Vector ku;
      system.applyStiffness(*mode, ku);
      EXPECT_LE(ku.cwiseAbs().maxCoeff(), 1e-12 * scale) << "order " << order;
    }
    // positive semi-definite with exactly three zero eigenvalues (no spurious zero-energy modes)
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(0.5 * (k + k.transpose()));
    int zeros = 0;
    for (Index i = 0; i < eigen.eigenvalues().size(); ++i) {
      EXPECT_GT(eigen.eigenvalues()[i], -1e-12 * scale);
      if (std::abs(eigen.eigenvalues()[i]) < 1e-10 * scale) ++zeros;
    }
    EXPECT_EQ(zeros, 3) << "order " << order;
  }
}

TEST(SpectralElementElasticity, UniformStrainLeavesOnlyBoundaryTractions) {
  for (int order : {1, 2, 4, 7}) {
    const SpectralElementSettings<2> settings = box(order, 0.5);
    const SpectralElementElasticity<2> system(settings);
    const Real lambda = settings.material.lambda(), mu = settings.material.mu();
    // u = G x with a general displacement gradient G
    Mat2 g;
    g << 0.3, -0.2, 0.5, 0.1;
    const Index n = system.nodeCount();
    Vector u(2 * n);
    for (Index p = 0; p < n; ++p) {
      const Vec2 x = system.nodePosition(p);
      u.segment<2>(2 * p) = g * x;
    }
    Vector ku;
    system.applyStiffness(u, ku);
    const Mat2 strain = 0.5 * (g + g.transpose());
    const Mat2 stress = lambda * strain.trace() * Mat2::Identity() + 2 * mu * strain;
    const ParticleSet<2> nodes = system.nodeParticles();
    Vec2 plusX = Vec2::Zero();
    for (Index p = 0; p < n; ++p) {
      const std::uint8_t faces = nodes.faceMask[static_cast<std::size_t>(p)];
      if (faces == 0) {
        EXPECT_LE(ku.segment<2>(2 * p).cwiseAbs().maxCoeff(), 1e-12) << "order " << order << " node " << p;
      } else if (faces == 2) {  // +x face only (no corner)
        plusX += ku.segment<2>(2 * p);
      }
    }
    // K u = the work-equivalent boundary forces: on the +x face (corners excepted, each of which
    // carries half an element edge's end weight) they sum to sigma n times the face's length less
    // the corners' shares; compare with the whole face by adding the corners' parts back.
    const Real h = settings.elementSize;
    const Real cornerWeight = 2.0 / (order * (order + 1)) * 0.5 * h;  // GLL end weight times h / 2
    const Real length = settings.upper[1] - settings.lower[1];
    const Vec2 expected = stress * Vec2(1, 0) * (length - 2 * cornerWeight);
    EXPECT_LE((plusX - expected).cwiseAbs().maxCoeff(), 1e-11) << "order " << order;
  }
}

TEST(SpectralElementElasticity, MassDashpotsAndStripLoadIntegrateWhatTheyShould) {
  SpectralElementSettings<2> s = box(4, 0.5, Vec2(-2, -1), Vec2(2, 0));
  s.faces = {SpectralElementFace::Absorbing, SpectralElementFace::Absorbing, SpectralElementFace::Absorbing,
             SpectralElementFace::Free};
  SpectralElementTraction<2> load;
  load.face = 3;
  load.centre = Vec2(0, 0);
  load.halfWidth = Vec2(0.5, 0);
  load.traction = Vec2(0.25, -1);
  load.history = [](Real t) { return 2 * t; };
  s.tractions.push_back(load);
  const SpectralElementElasticity<2> system(s);
  EXPECT_EQ(system.nodeCount(), (8 * 4 + 1) * (2 * 4 + 1));
  const Vector m = system.lumpedMass();
  EXPECT_NEAR(m.sum(), 2 * s.material.density() * 4 * 1, 1e-12);  // two components
  EXPECT_GT(m.minCoeff(), 0);
  const Real rho = s.material.density(), cp = s.material.pWaveSpeed(), cs = s.material.sWaveSpeed();
  const Vector& c = system.dampingDiagonal();
  // total dashpot per component: normal rho c_p on its faces' length, tangential rho c_s
  Real cx = 0, cy = 0;
  for (Index p = 0; p < system.nodeCount(); ++p) {
    cx += c[2 * p];
    cy += c[2 * p + 1];
  }
  EXPECT_NEAR(cx, rho * cp * 2 * 1 + rho * cs * 4, 1e-12);  // +-x faces normal, -y face tangential
  EXPECT_NEAR(cy, rho * cs * 2 * 1 + rho * cp * 4, 1e-12);
  EXPECT_TRUE(system.hasDamping());
  Vector f;
  system.force(0.75, f);
  Real fx = 0, fy = 0;
  for (Index p = 0; p < system.nodeCount(); ++p) {
    fx += f[2 * p];
    fy += f[2 * p + 1];
    if (f.segment<2>(2 * p).squaredNorm() > 0) {
      EXPECT_NEAR(system.nodePosition(p)[1], 0, 1e-15);
      EXPECT_LE(std::abs(system.nodePosition(p)[0]), 0.5 + 1e-12);
    }
  }
  EXPECT_NEAR(fx, 0.25 * 1.0 * 1.5, 1e-13);  // traction * width * f(0.75)
  EXPECT_NEAR(fy, -1.0 * 1.0 * 1.5, 1e-13);
  // node lookup and the GLL nodes as particles
  EXPECT_GE(system.nodeAt(Vec2(0, 0)), 0);
  EXPECT_EQ(system.nodeAt(Vec2(0.1, 0)), -1);
  const ParticleSet<2> particles = system.nodeParticles();
  EXPECT_EQ(particles.size(), system.nodeCount());
  EXPECT_NEAR((particles.position(system.nodeAt(Vec2(2, 0))) - Vec2(2, 0)).norm(), 0, 1e-15);
}

TEST(SpectralElementElasticity, FixedFacesAreMaskedSymmetrically) {
  SpectralElementSettings<2> s = box(3, 0.5);
  s.faces[0] = SpectralElementFace::Fixed;
  s.faces[2] = SpectralElementFace::Fixed;
  const SpectralElementElasticity<2> system(s);
  // K symmetric on the whole vector space: x^T K y = y^T K x for random x, y
  const Vector x = Vector::Random(system.size()), y = Vector::Random(system.size());
  Vector kx, ky;
  system.applyStiffness(x, kx);
  system.applyStiffness(y, ky);
  EXPECT_NEAR(y.dot(kx), x.dot(ky), 1e-12 * std::abs(y.dot(kx)));
  for (Index dof = 0; dof < system.size(); ++dof)
    if (system.fixedDofs()[static_cast<std::size_t>(dof)]) {
      EXPECT_EQ(kx[dof], 0);
    }
  EXPECT_FALSE(system.hasDamping());
  // the Gershgorin row sums bound the true ones
  const Vector sums = system.stiffnessAbsoluteRowSums();
  Vector unit = Vector::Zero(system.size()), column;
  for (Index j = 0; j < system.size(); j += 7) {
    unit.setZero();
    unit[j] = 1;
    system.applyStiffness(unit, column);
    EXPECT_LE(std::abs(column[j]), sums[j] + 1e-12);
  }
}

TEST(SpectralElementElasticity, RefusesBadInput) {
  EXPECT_THROW(SpectralElementElasticity<2>(box(0, 0.5)), InputError);
  EXPECT_THROW(SpectralElementElasticity<2>(box(9, 0.5)), InputError);
  try {
    SpectralElementElasticity<2> system(box(4, 0.4));  // 3 / 0.4 is not whole
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "elementSize");
  }
  SpectralElementSettings<2> s = box(4, 0.5);
  SpectralElementTraction<2> load;
  load.face = 3;
  load.centre = Vec2(1.8, 0);
  load.halfWidth = Vec2(0.5, 0);  // ends at 2.3, beyond the face's end at 2
  load.traction = Vec2(0, 1);
  load.history = [](Real) { return 1.0; };
  s.tractions.push_back(load);
  try {
    SpectralElementElasticity<2> system(s);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "traction");
  }
}

// A strip whose ends fall inside elements: its load vector is still the exact integral of T phi_i
// (total force, first moment), and with ends on element boundaries it is the GLL rule's.
TEST(SpectralElementElasticity, StripLoadIsExactWithEndsInsideElements) {
  for (int order : {1, 2, 4, 8}) {
    SpectralElementSettings<2> s = box(order, 1.0, Vec2(-3, -2), Vec2(3, 0));
    SpectralElementTraction<2> load;
    load.face = 3;
    load.centre = Vec2(0.2, 0);
    load.halfWidth = Vec2(0.55, 0);  // [-0.35, 0.75]
    load.traction = Vec2(0, -2);
    load.history = [](Real) { return 1.0; };
    s.tractions.push_back(load);
    const SpectralElementElasticity<2> system(s);
    Vector f;
    system.force(0, f);
    Real total = 0, moment = 0;
    for (Index p = 0; p < system.nodeCount(); ++p) {
      total += f[2 * p + 1];
      moment += f[2 * p + 1] * system.nodePosition(p)[0];
    }
    // sum_i phi_i = 1 and sum_i x_i phi_i = x (order >= 1): the force and its first moment
    EXPECT_NEAR(total, -2 * 1.1, 1e-13) << "order " << order;
    EXPECT_NEAR(moment, -2 * 0.5 * (0.75 * 0.75 - 0.35 * 0.35), 1e-13) << "order " << order;
  }
}

}  // namespace
}  // namespace mfwave
