#include "spectra/MethodLatticeStencils.hpp"

#include "numerics/RestModes.hpp"
#include "core/Error.hpp"
#include "kernels/KernelFactory.hpp"
#include "methods/collocation/RadialBasisShapeFunctions.hpp"
#include "methods/collocation/ReproducingKernelShapeFunctions.hpp"
#include "methods/finite_difference/FiniteDifferenceWaveOperator.hpp"
#include "methods/updated_lagrangian_sph/UpdatedLagrangianSph.hpp"
#include "neighbours/CellList.hpp"
#include "neighbours/NeighbourList.hpp"
#include "particles/BoxFace.hpp"
#include "particles/Lattice.hpp"

#include <cmath>
#include <memory>
#include <string>

namespace mfwave {

namespace {

void checkSpacing(Real spacing) {
  if (!(spacing > 0) || !std::isfinite(spacing)) throw InputError("spacing", "must be positive and finite");
}

template <int D>
ParticleSet<D> block(int halfWidth, Real spacing) {
  const Vec<D> upper = Vec<D>::Constant(halfWidth * spacing);
  return makeLattice<D>(-upper, upper, spacing);
}

template <int D>
Index particleAt(const ParticleSet<D>& particles, const Vec<D>& x, Real spacing) {
  for (Index i = 0; i < particles.physicalCount(); ++i)
    if ((particles.position(i) - x).norm() < 1e-9 * spacing) return i;
  throw Error("method lattice stencil: no lattice particle at the expected position");
}

template <int D>
Vec<D> nextAlongX(Real spacing) {
  Vec<D> x = Vec<D>::Zero();
  x(0) = spacing;
  return x;
}

// Collocation rows at node `at` as lattice stencils.
template <int D>
void collocationRow(const ShapeFunctions<D>& shapes, const ParticleSet<D>& nodes, Index at, const Material& material,
                    LatticeStencil<D>& mass, LatticeStencil<D>& acceleration) {
  const Vec<D> x = nodes.position(at);
  mass = LatticeStencil<D>{};
  acceleration = LatticeStencil<D>{};
  mass.components = acceleration.components = D;
  collocationRowBlocks<D>(shapes, x, material, [&](Index node, Real psi, const Mat<D>& g) {
    const Vec<D> r = nodes.position(node) - x;
    mass.offsets.push_back(r);
    mass.blocks.push_back(psi * Eigen::MatrixXd::Identity(D, D));
    acceleration.offsets.push_back(r);
    acceleration.blocks.push_back(Eigen::MatrixXd(g));
  });
}

}  // namespace

template <int D>
void collocationRowBlocks(const ShapeFunctions<D>& shapes, const Vec<D>& x, const Material& material,
                          const std::function<void(Index node, Real psi, const Mat<D>& acceleration)>& block) {
  ShapeFunctionValues<D> values;
  shapes.evaluate(x, 2, values);
  const Real lambda = material.lambda(), mu = material.mu(), rho = material.density();
  for (Index k = 0; k < values.size(); ++k) {
    const auto at = static_cast<std::size_t>(k);
    const Mat<D>& H = values.hessian[at];
    block(values.nodes[at], values.value[at], ((lambda + mu) * H + mu * H.trace() * Mat<D>::Identity()) / rho);
  }
}

UpdatedLagrangianSphOptions linearisedAboutRest(UpdatedLagrangianSphOptions options) {
  options.viscosity.alpha = 0;
  options.viscosity.beta = 0;
  options.artificialStress.enabled = false;
  return options;
}

template <int D>
MethodLatticeStencil<D> finiteDifferenceInteriorStencil(Real spacing, Real waveSpeed) {
  checkSpacing(spacing);
  if (!(waveSpeed > 0) || !std::isfinite(waveSpeed)) throw InputError("wave_speed", "must be positive and finite");
  MethodLatticeStencil<D> result;
  result.halfWidth = 3;
  const ParticleSet<D> particles = block<D>(result.halfWidth, spacing);
  FiniteDifferenceWaveOptions options;
  options.spacing = spacing;
  options.density = 1;
  options.modulus = waveSpeed * waveSpeed;
  options.fixedFaces = allFaces(D);  // boundary rows left out; the centre row is interior
  const LinearSecondOrderSystem system =
      assembleFiniteDifferenceWave(particles, buildNeighbourList(CellList<D>(particles, 1.2 * spacing)), options);
  result.acceleration = extractLatticeStencil(system, particles, particleAt<D>(particles, Vec<D>::Zero(), spacing));
  result.translationDifference = stencilDifference(
      result.acceleration, extractLatticeStencil(system, particles, particleAt<D>(particles, nextAlongX<D>(spacing), spacing)),
      1e-9 * spacing);
  return result;
}

template <int D>
MethodLatticeStencil<D> collocationInteriorStencil(CollocationBasis basis, int order, Real ratio,
                                                   const Material& material, Real spacing, int halfWidth) {
  checkSpacing(spacing);
  if (!(ratio > 0) || !std::isfinite(ratio)) throw InputError("support_ratio", "must be positive and finite");
  if (basis == CollocationBasis::ReproducingKernel && (order < 1 || order > 3))
    throw InputError("order", "the RK basis order must be 1, 2 or 3, got " + std::to_string(order));
  MethodLatticeStencil<D> result;
  result.halfWidth = halfWidth > 0 ? halfWidth
                     : basis == CollocationBasis::ReproducingKernel ? static_cast<int>(std::ceil(ratio)) + 2
                                                                    : (D == 1 ? 40 : 10);
  const ParticleSet<D> nodes = block<D>(result.halfWidth, spacing);
  std::unique_ptr<ShapeFunctions<D>> shapes;
  if (basis == CollocationBasis::ReproducingKernel)
    shapes = std::make_unique<ReproducingKernelShapeFunctions<D>>(nodes, order, ratio * spacing);
  else
    shapes = std::make_unique<RadialBasisShapeFunctions<D>>(
        nodes, RadialBasisFunction(RadialBasisKind::InverseMultiquadric, ratio * spacing));
  collocationRow<D>(*shapes, nodes, particleAt<D>(nodes, Vec<D>::Zero(), spacing), material, result.mass,
                    result.acceleration);
  LatticeStencil<D> nextMass, nextAcceleration;
  collocationRow<D>(*shapes, nodes, particleAt<D>(nodes, nextAlongX<D>(spacing), spacing), material, nextMass,
                    nextAcceleration);
  // A global (RB) row reaches the block's edge, so the neighbour's row covers other offsets on
  // either side: compare on the offsets both have.
  result.translationDifference = stencilDifference(result.acceleration, nextAcceleration, 1e-9 * spacing,
                                                   basis == CollocationBasis::RadialBasis);
  return result;
}

template <int D>
MethodLatticeStencil<D> updatedLagrangianSphInteriorStencil(UpdatedLagrangianSphOptions options, Real spacing) {
  checkSpacing(spacing);
  options = linearisedAboutRest(options);
  const auto kernel = makeKernel(options.kernel, D, options.smoothingLengthRatio * spacing);
  // Lattice steps inside the (open) support along an axis.
  const int reach = static_cast<int>(std::ceil(kernel->supportRadius() / spacing - 1e-9)) - 1;
  MethodLatticeStencil<D> result;
  // The stencil is read from the centre's column of the rest operator: on a lattice
  // (A u)_a = sum_r G_r u_{a + r} gives G_r = A(c - r, c), so D perturbations of the centre's
  // velocity give every block (its rows would take a perturbation per unknown of the block: hours
  // in 3-D). The rows c - r reach two supports from the centre (the force reads the neighbours'
  // stresses, whose rates read their own neighbours) and must themselves be interior rows, whose
  // corrections and sums see a full neighbourhood: three supports, plus one spacing for the
  // translation check from the next particle's column.
  result.halfWidth = 3 * reach + 1;
  const ParticleSet<D> particles = block<D>(result.halfWidth, spacing);
  UpdatedLagrangianSph<D> system(particles, options);
  const Vector rest = system.initialState(Vector());
  std::vector<Index> velocities;
  for (Index i = 0; i < particles.physicalCount(); ++i)
    for (int a = 0; a < D; ++a) velocities.push_back(system.layout().velocity(i, a));

  const Index centre = particleAt<D>(particles, Vec<D>::Zero(), spacing);
  const Index next = particleAt<D>(particles, nextAlongX<D>(spacing), spacing);
  std::vector<Index> columns;
  for (const Index particle : {centre, next})
    for (int a = 0; a < D; ++a) columns.push_back(particle * D + a);
  const Eigen::MatrixXd A = restOperatorColumns(system, 0, rest, velocities, columns);

  auto stencilOf = [&](Index particle, Index firstColumn) {
    LatticeStencil<D> stencil;
    stencil.components = D;
    const Real largest = A.middleCols(firstColumn, D).cwiseAbs().maxCoeff();
    // Rows in descending order: offsets x_particle - x_b ascend as for a row read left to right.
    for (Index b = particles.physicalCount() - 1; b >= 0; --b) {
      Eigen::MatrixXd g = A.block(b * D, firstColumn, D, D);
      // Particles beyond two supports get exactly zero. The finite-difference noise of the coupled
      // entries is about 1e-13 of the largest (a stable row's smallest omega^2 comes out at -1e-13
      // of omega^2_max), so only entries below that are dropped: at 1e-9 the quintic kernel's real
      // tail couplings were cut, which broke the rigid translation's zero by 2e-10 and read as
      // growth (2-D at h / dx = 2, 3-D at 1.2 and 1.3).
      if (g.cwiseAbs().maxCoeff() <= 1e-13 * largest) continue;
      stencil.offsets.push_back(particles.position(particle) - particles.position(b));
      stencil.blocks.push_back(std::move(g));
    }
    return stencil;
  };
  result.acceleration = stencilOf(centre, 0);
  result.translationDifference = stencilDifference(result.acceleration, stencilOf(next, D), 1e-9 * spacing);
  return result;
}

#define MFWAVE_METHOD_LATTICE_STENCILS(D)                                                                       \
  template void collocationRowBlocks<D>(const ShapeFunctions<D>&, const Vec<D>&, const Material&,               \
                                        const std::function<void(Index, Real, const Mat<D>&)>&);                \
  template MethodLatticeStencil<D> finiteDifferenceInteriorStencil<D>(Real, Real);                              \
  template MethodLatticeStencil<D> collocationInteriorStencil<D>(CollocationBasis, int, Real, const Material&,  \
                                                                 Real, int);                                    \
  template MethodLatticeStencil<D> updatedLagrangianSphInteriorStencil<D>(UpdatedLagrangianSphOptions, Real);
MFWAVE_METHOD_LATTICE_STENCILS(1)
MFWAVE_METHOD_LATTICE_STENCILS(2)
MFWAVE_METHOD_LATTICE_STENCILS(3)
#undef MFWAVE_METHOD_LATTICE_STENCILS

}  // namespace mfwave
