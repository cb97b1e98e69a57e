// The Galerkin variant on cut lattice cells (CutCellGalerkin): on an uncut box it is the lattice's
// Galerkin assembly; on a disc, a ball and an inclined half-plane its volume and surface are the
// solid's to 1e-3, rigid motions cost no energy and a uniform strain the solid's volume times its
// energy density, the small-cell extension keeps the stable step within the stated fraction of the
// uncut lattice's, point forces and moment tensors carry their resultant and first moment, and
// two materials meet where their regions do. Staircasing keeps whole cells.

#include "core/Error.hpp"
#include "methods/very_weak_sph/CutCellGalerkin.hpp"
#include "methods/very_weak_sph/GalerkinLattice.hpp"
#include "numerics/StableTimeStep.hpp"
#include "particles/Lattice.hpp"
#include "systems/LinearSecondOrderSystem.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

namespace mfwave::cut_cell_test {
namespace {

const Material kSolid = Material::fromLame(2.0, 1.0, 1.3);
constexpr Real kPi = 3.14159265358979323846;

template <int D>
CutCellDomain<D> solidOf(std::function<Real(const Vec<D>&)> distance) {
  CutCellDomain<D> domain;
  domain.distance = std::move(distance);
  domain.materials = {kSolid};
  domain.materialAt = [](const Vec<D>&) { return 0; };
  return domain;
}

template <int D>
CutCellSettings<D> boxOf(Real half, Real spacing) {
  CutCellSettings<D> s;
  s.lower = Vec<D>::Constant(-half);
  s.upper = Vec<D>::Constant(half);
  s.spacing = spacing;
  return s;
}

template <int D>
Vector fieldOf(const CutCellGalerkin<D>& g, const std::function<Vec<D>(const Vec<D>&)>& u) {
  Vector out(g.size());
  for (Index a = 0; a < g.unknownNodes(); ++a) out.template segment<D>(D * a) = u(g.unknownPositions()[static_cast<std::size_t>(a)]);
  return out;
}

TEST(CutCellGalerkin, UncutBoxIsTheLatticeAssembly) {
  // A solid that contains the whole box: no cell is cut, and the rows are GalerkinLattice's.
  const CutCellSettings<2> box = boxOf<2>(1.0, 0.25);
  const CutCellGalerkin<2> cut(solidOf<2>([](const Vec2&) { return -10.0; }), box);
  EXPECT_EQ(cut.cutCells(), 0);
  EXPECT_EQ(cut.extendedNodes(), 0);
  const ParticleSet<2> particles = makeLattice<2>(box.lower, box.upper, box.spacing);
  const GalerkinLattice<2> lattice = assembleGalerkinLattice<2>(particles, kSolid);
  ASSERT_EQ(cut.size(), lattice.stiffness.rows());
  // the cut assembly numbers nodes in its own order: match them by position
  std::vector<Index> order(static_cast<std::size_t>(cut.unknownNodes()));
  for (Index a = 0; a < cut.unknownNodes(); ++a) {
    const Vec2 x = cut.unknownPositions()[static_cast<std::size_t>(a)];
    Index best = -1;
    for (Index p = 0; p < particles.physicalCount(); ++p)
      if ((particles.position(p) - x).norm() < 1e-9) best = p;
    ASSERT_GE(best, 0);
    order[static_cast<std::size_t>(a)] = best;
  }
  const Eigen::MatrixXd k = Eigen::MatrixXd(cut.stiffness()), reference = Eigen::MatrixXd(lattice.stiffness);
  Real worst = 0;
  for (Index a = 0; a < cut.unknownNodes(); ++a)
    for (Index b = 0; b < cut.unknownNodes(); ++b)
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
          worst = std::max(worst, std::abs(k(2 * a + i, 2 * b + j) -
                                           reference(2 * order[static_cast<std::size_t>(a)] + i, 2 * order[static_cast<std::size_t>(b)] + j)));
  EXPECT_LE(worst, 1e-12 * reference.cwiseAbs().maxCoeff());
  for (Index a = 0; a < cut.unknownNodes(); ++a)
    EXPECT_NEAR(cut.mass().coeff(2 * a, 2 * a), lattice.mass.coeff(2 * order[static_cast<std::size_t>(a)], 2 * order[static_cast<std::size_t>(a)]), 1e-14);
}

TEST(CutCellGalerkin, DiscVolumeSurfaceAndPatchTests) {
  const CutCellGalerkin<2> disc(solidOf<2>([](const Vec2& x) { return x.norm() - 1.0; }), boxOf<2>(1.25, 0.1));
  EXPECT_NEAR(disc.volume() / kPi, 1.0, 1e-3);
  Real perimeter = 0;
  for (const auto& p : disc.surface()) {
    perimeter += p.weight;
    EXPECT_NEAR(p.normal.dot(p.x.normalized()), 1.0, 0.02) << "the outward normal at " << p.x.transpose();
  }
  EXPECT_NEAR(perimeter / (2 * kPi), 1.0, 1e-3);
  EXPECT_GT(disc.cutCells(), 0);
  // rigid translations and rotation: no force
  const Vector k = Eigen::MatrixXd(disc.stiffness()).cwiseAbs().rowwise().sum();
  for (const auto& rigid : {std::function<Vec2(const Vec2&)>([](const Vec2&) { return Vec2(1, 0); }),
                            std::function<Vec2(const Vec2&)>([](const Vec2&) { return Vec2(0, 1); }),
                            std::function<Vec2(const Vec2&)>([](const Vec2& x) { return Vec2(-x[1], x[0]); })}) {
    const Vector u = fieldOf<2>(disc, rigid);
    const Vector f = disc.stiffness() * u;
    EXPECT_LE(f.cwiseAbs().maxCoeff(), 1e-12 * k.maxCoeff());
  }
  // a uniform strain: u^T K u = volume eps : C : eps (the interpolant is exactly linear, extension included)
  const Vector u = fieldOf<2>(disc, [](const Vec2& x) { return Vec2(0.01 * x[0] + 0.004 * x[1], 0.003 * x[0] - 0.02 * x[1]); });
  const Real exx = 0.01, eyy = -0.02, exy = 0.5 * (0.004 + 0.003);
  const Real density = 0.5 * kSolid.lambda() * (exx + eyy) * (exx + eyy) + kSolid.mu() * (exx * exx + eyy * eyy + 2 * exy * exy);
  EXPECT_NEAR(0.5 * u.dot(disc.stiffness() * u) / (density * kPi), 1.0, 1e-3);
}

TEST(CutCellGalerkin, BallVolumeAndSurfaceIn3d) {
  const CutCellGalerkin<3> ball(solidOf<3>([](const Vec3& x) { return x.norm() - 1.0; }), boxOf<3>(1.2, 0.2));
  EXPECT_NEAR(ball.volume() / (4.0 / 3.0 * kPi), 1.0, 1e-3);
  // the surface: one point per cut sub-cell with the tangent plane's area in it
  Real area = 0;
  Vec3 pressure = Vec3::Zero();
  for (const auto& p : ball.surface()) {
    area += p.weight;
    pressure += p.weight * p.normal;
    EXPECT_NEAR(p.normal.dot(p.x.normalized()), 1.0, 1e-3);
  }
  EXPECT_NEAR(area / (4 * kPi), 1.0, 1e-3);
  EXPECT_LE(pressure.norm(), 1e-3 * area) << "a uniform pressure on a closed surface has no resultant";
  const Vector u = fieldOf<3>(ball, [](const Vec3& x) { return Vec3(x[1], -x[0], 0.5); });
  EXPECT_LE((ball.stiffness() * u).cwiseAbs().maxCoeff(), 1e-11);
}

// The stable step of central differences on cut solids against the uncut lattice of the same
// spacing: a disc at 25 offsets against the lattice and half-planes at 17 inclinations, with the
// small-cell extension (fraction 0.25) and with every node kept. The stated bound is 0.5.
TEST(CutCellGalerkin, SmallCellsKeepTheStableStep) {
  auto step = [](const CutCellGalerkin<2>& g) {
    const LinearSecondOrderSystem system(g.mass(), SparseMatrix(), g.stiffness());
    return centralDifferenceStableStep(system, 1e-8).estimate();
  };
  const CutCellGalerkin<2> uncut(solidOf<2>([](const Vec2&) { return -10.0; }), boxOf<2>(1.25, 0.1));
  const Real reference = step(uncut);
  Real worstExtended = 1e300, worstKept = 1e300;
  std::vector<std::function<Real(const Vec2&)>> solids;
  for (int k = 0; k < 25; ++k) {
    const Real shift = 0.004 * k;
    solids.emplace_back([shift](const Vec2& x) { return (x - Vec2(shift, 0.6 * shift)).norm() - 1.0; });
  }
  for (int k = 1; k < 18; ++k) {
    const Real angle = kPi / 2 * k / 18;
    const Vec2 n(-std::sin(angle), std::cos(angle));
    solids.emplace_back([n](const Vec2& x) { return n.dot(x - Vec2(0.013, 0.021)); });
  }
  for (const auto& solid : solids) {
    CutCellSettings<2> s = boxOf<2>(1.25, 0.1);
    worstExtended = std::min(worstExtended, step(CutCellGalerkin<2>(solidOf<2>(solid), s)) / reference);
    s.smallCellFraction = 0;
    worstKept = std::min(worstKept, step(CutCellGalerkin<2>(solidOf<2>(solid), s)) / reference);
  }
  std::printf("stable step / uncut over %zu solids: with the extension >= %.3f, every node kept >= %.3f\n",
              solids.size(), worstExtended, worstKept);
  EXPECT_GE(worstExtended, 0.5);
  EXPECT_LT(worstKept, 0.5);
}

TEST(CutCellGalerkin, InclinedSurfaceAndLoads) {
  // the half-plane below a line through the origin at 30 degrees
  const Real angle = kPi / 6;
  const Vec2 outward(-std::sin(angle), std::cos(angle));
  const CutCellGalerkin<2> half(solidOf<2>([outward](const Vec2& x) { return outward.dot(x); }), boxOf<2>(2.0, 0.0625));
  for (const auto& p : half.surface()) EXPECT_NEAR(p.normal.dot(outward), 1.0, 1e-9);
  // a strip of width 1 centred at the origin pressing along the inward normal with unit traction
  const Vector f = half.surfaceTraction([](const Vec2& x) { return x.norm() <= 0.5; },
                                        [](const Vec2&, const Vec2& n) { return Vec2(-n); });
  Vec2 total = Vec2::Zero();
  for (Index a = 0; a < half.unknownNodes(); ++a) total += f.segment<2>(2 * a);
  EXPECT_NEAR(total.dot(-outward), 1.0, 1e-3) << "resultant " << total.transpose();
  // a point force and a moment tensor anywhere
  const Vec2 source(-0.37, -0.81);
  const Vector force = half.pointForce(source, Vec2(0.3, -2.0));
  Vec2 sum = Vec2::Zero();
  for (Index a = 0; a < half.unknownNodes(); ++a) sum += force.segment<2>(2 * a);
  EXPECT_NEAR((sum - Vec2(0.3, -2.0)).norm(), 0, 1e-12);
  Mat2 moment;
  moment << 1.0, 0.4, 0.4, -0.5;
  const Vector m = half.momentTensor(source, moment);
  Vec2 resultant = Vec2::Zero();
  Mat2 first = Mat2::Zero();
  for (Index a = 0; a < half.unknownNodes(); ++a) {
    resultant += m.segment<2>(2 * a);
    first += m.segment<2>(2 * a) * half.unknownPositions()[static_cast<std::size_t>(a)].transpose();
  }
  EXPECT_LE(resultant.norm(), 1e-12);
  EXPECT_LE((first - moment).norm(), 1e-12) << first;
}

TEST(CutCellGalerkin, TwoMaterials) {
  // Below y = level the solid is three times as dense and stiff. The cells the interface crosses are
  // split to 2^depth sub-cells; at the last level each Gauss point takes its own material: the mass
  // is exact when the interface lies on the sub-cells' grid, else within one sub-cell's strip.
  for (const Real level : {0.3125, 0.3}) {
    CutCellDomain<2> domain = solidOf<2>([](const Vec2&) { return -10.0; });
    domain.materials = {kSolid, Material::fromLame(6.0, 3.0, 3.9)};
    domain.materialAt = [level](const Vec2& x) { return x[1] < level ? 1 : 0; };
    domain.interfaceDistance = [level](const Vec2& x) { return std::abs(x[1] - level); };
    const CutCellSettings<2> box = boxOf<2>(1.0, 0.25);
    const CutCellGalerkin<2> layered(domain, box);
    const Real mass = Vector(layered.mass().diagonal()).sum() / 2;
    const Real exact = 1.3 * 2 * (1 - level) + 3.9 * 2 * (1 + level);
    const Real strip = box.spacing / (1 << box.depth) * 2 * (3.9 - 1.3);
    EXPECT_NEAR(mass, exact, level == 0.3125 ? 1e-12 : strip) << "interface at y = " << level;
  }
}

TEST(CutCellGalerkin, StaircaseKeepsWholeCells) {
  CutCellSettings<2> s = boxOf<2>(1.25, 0.1);
  s.cells = CutCells::Staircase;
  const CutCellGalerkin<2> stairs(solidOf<2>([](const Vec2& x) { return x.norm() - 1.0; }), s);
  const Real cells = stairs.volume() / 0.01;
  EXPECT_NEAR(cells, std::round(cells), 1e-9);
  EXPECT_GT(std::abs(stairs.volume() / kPi - 1), 1e-3) << "a staircase misses the disc's area";
}

TEST(CutCellGalerkin, RefusesWhatItCannotResolve) {
  try {
    const CutCellGalerkin<2> nothing(solidOf<2>([](const Vec2& x) { return x.norm() - 5.0 + 10.0; }), boxOf<2>(1.0, 0.25));
    FAIL() << "an empty solid";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "geometry");
  }
  try {
    // a sliver thinner than the lattice: a strip 0.02 wide
    const CutCellGalerkin<2> sliver(solidOf<2>([](const Vec2& x) { return std::abs(x[1] - 0.01) - 0.01; }), boxOf<2>(1.0, 0.25));
    FAIL() << "a sliver";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "geometry");
  }
}


// Materials by region on the cut lattice (issue 48): a plane P pulse at normal incidence on the
// interface y = 0 between two materials of impedance ratio 3 (wave speeds 1 : 2) splits into a
// reflected displacement -1/2 and a transmitted 1/2 of the incident (the exact (Z1 - Z2) / (Z1 + Z2)
// and 2 Z1 / (Z1 + Z2)). A wide box keeps its free side faces' waves away from the middle column,
// where the amplitudes are fitted to the exact shapes: within 1 % (measured -0.50103 and 0.49988).
TEST(CutCellGalerkin, InterfaceOfImpedanceRatioThree) {
  const Material upper = Material::fromLame(1.0, 1.0, 1.0), lower = Material::fromLame(6.0, 6.0, 1.5);
  CutCellDomain<2> domain = solidOf<2>([](const Vec2&) { return -100.0; });
  domain.materials = {upper, lower};
  domain.materialAt = [](const Vec2& x) { return x[1] > 0 ? 0 : 1; };
  domain.interfaceDistance = [](const Vec2& x) { return std::abs(x[1]); };
  CutCellSettings<2> s;
  s.lower = Vec2(-12, -8);
  s.upper = Vec2(12, 5);
  s.spacing = 0.0625;
  const CutCellGalerkin<2> g(domain, s);
  const Real c1 = upper.pWaveSpeed(), c2 = lower.pWaveSpeed(), y0 = 2.5, w = 1.0;
  auto bump = [w](Real r) { const Real q = r / w; return std::abs(q) < 1 ? std::pow(1 - q * q, 4) : 0.0; };
  const Index n = g.size();
  Vector u = Vector::Zero(n), previous = Vector::Zero(n);
  const Real end = 2 * y0 / c1;
  const Real dt = 0.004;
  const auto steps = static_cast<Index>(std::ceil(end / dt));
  const Real step = end / static_cast<Real>(steps);
  for (Index a = 0; a < g.unknownNodes(); ++a) {
    const Real y = g.unknownPositions()[static_cast<std::size_t>(a)][1];
    u[2 * a + 1] = bump(y - y0);
    previous[2 * a + 1] = bump(y - y0 - c1 * step);
  }
  const Vector inverseMass = Vector(g.mass().diagonal()).cwiseInverse();
  Vector next(n);
  for (Index k = 0; k < steps; ++k) {
    next = 2 * u - previous - step * step * inverseMass.cwiseProduct(g.stiffness() * u);
    previous.swap(u);
    u.swap(next);
  }
  // the middle column's nodes: fitted amplitudes with the trapezoidal weights of the column
  Real rg = 0, gg = 0, tg = 0, hh = 0, misfitR = 0, misfitT = 0;
  for (Index a = 0; a < g.unknownNodes(); ++a) {
    const Vec2 x = g.unknownPositions()[static_cast<std::size_t>(a)];
    if (std::abs(x[0]) > 1e-9) continue;
    const Real uy = u[2 * a + 1];
    if (x[1] > 0) {
      const Real e = bump(y0 - x[1]);
      rg += uy * e;
      gg += e * e;
      misfitR += uy * uy;
    } else if (x[1] < 0) {
      const Real e = bump(x[1] * c1 / c2 + y0);
      tg += uy * e;
      hh += e * e;
      misfitT += uy * uy;
    }
  }
  const Real reflected = rg / gg, transmitted = tg / hh;
  const Real z1 = upper.density() * c1, z2 = lower.density() * c2;
  std::printf("cut-cell Galerkin: reflected %.5f (exact %.5f), transmitted %.5f (exact %.5f)\n", reflected,
              (z1 - z2) / (z1 + z2), transmitted, 2 * z1 / (z1 + z2));
  EXPECT_NEAR(reflected / ((z1 - z2) / (z1 + z2)), 1.0, 0.01);
  EXPECT_NEAR(transmitted / (2 * z1 / (z1 + z2)), 1.0, 0.01);
  // the shapes: the lattice's dispersion trails each pulse by a few per cent at 16 spacings per half-width
  EXPECT_LT(std::sqrt(std::max<Real>(0, misfitR - reflected * reflected * gg)) / (std::abs(reflected) * std::sqrt(gg)), 0.05);
  EXPECT_LT(std::sqrt(std::max<Real>(0, misfitT - transmitted * transmitted * hh)) / (transmitted * std::sqrt(hh)), 0.05);
}

}  // namespace
}  // namespace mfwave::cut_cell_test
