#include "methods/very_weak_sph/VeryWeakSphProblem.hpp"

#include "core/Error.hpp"
#include "kernels/KernelFactory.hpp"
#include "lattice/SymmetryFold.hpp"
#include "methods/very_weak_sph/Deconvolution.hpp"
#include "methods/very_weak_sph/LatticePatchLoad.hpp"
#include "methods/very_weak_sph/PatchLoad.hpp"
#include "methods/very_weak_sph/VeryWeakSphLattice.hpp"
#include "neighbours/CellList.hpp"
#include "particles/BoxFace.hpp"
#include "particles/Lattice.hpp"

#include <utility>

namespace mfwave {
namespace {

Real compressedRowsMiB(const SparseMatrix& m) {
  return (static_cast<Real>(m.nonZeros()) * (sizeof(Real) + sizeof(int)) +
          static_cast<Real>(m.outerSize() + 1) * sizeof(int)) / (1024.0 * 1024.0);
}

// The settings' combination checked before anything is built, then the kernel.
template <int D>
std::unique_ptr<Kernel> checkedKernel(const VeryWeakSphProblemSettings<D>& settings) {
  checkVeryWeakSphCombination(settings.options.variant, settings.deconvolution, settings.smoothingRate);
  if (settings.symmetryFaces != 0) {
    checkSymmetryFaces(settings.symmetryFaces, D, "boundary");
    // The planes are folded into the lattice's stencils (VeryWeakSphLattice.hpp); an assembly on
    // particles has no image to fold.
    if (settings.storage != OperatorStorage::Lattice)
      throw InputError("method.operator", "symmetry planes need the lattice storage (\"auto\" or \"lattice\")");
  }
  return makeKernel(settings.kernel, D, settings.smoothingLength);
}

template <int D>
bool onLattice(const VeryWeakSphProblemSettings<D>& settings) {
  return settings.storage == OperatorStorage::Lattice;
}

// The sparse path's neighbours and assembly; nothing for the lattice storage.
template <int D>
NeighbourList neighboursFor(const ParticleSet<D>& particles, const Kernel& kernel,
                            const VeryWeakSphProblemSettings<D>& settings) {
  if (onLattice(settings)) return NeighbourList();
  return buildNeighbourList(CellList<D>(particles, kernel.supportRadius()), particles.physicalCount());
}

template <int D>
VeryWeakSph<D> assemblyFor(const ParticleSet<D>& particles, const NeighbourList& neighbours, const Kernel& kernel,
                           const VeryWeakSphProblemSettings<D>& settings) {
  if (onLattice(settings)) return {VeryWeakSphData<D>{}, LinearSecondOrderSystem(SparseMatrix(), SparseMatrix(), SparseMatrix())};
  return assembleVeryWeakSph<D>(particles, neighbours, kernel, settings.options);
}

}  // namespace

template <int D>
Vector faceTractionLoad(const VeryWeakSphData<D>& data, std::uint8_t faces, const Vec<D>& traction) {
  Vector t = Vector::Zero(D * data.facets.count());
  for (Index f = 0; f < data.facets.count(); ++f)
    if (faces & faceBit(data.facets.face[static_cast<std::size_t>(f)])) t.template segment<D>(D * f) = traction;
  return data.tractionMatrix * t;
}

template Vector faceTractionLoad<1>(const VeryWeakSphData<1>&, std::uint8_t, const Vec<1>&);
template Vector faceTractionLoad<2>(const VeryWeakSphData<2>&, std::uint8_t, const Vec<2>&);
template Vector faceTractionLoad<3>(const VeryWeakSphData<3>&, std::uint8_t, const Vec<3>&);

void checkVeryWeakSphCombination(VeryWeakSphVariant variant, bool deconvolution, Real smoothingRate) {
  if (variant != VeryWeakSphVariant::Galerkin) return;
  if (deconvolution)
    throw InputError("method.deconvolution", "the galerkin variant's state is the nodal displacement; there is no "
                                             "kernel estimate to deconvolve (set it to false)");
  if (smoothingRate > 0)
    throw InputError("method.smoothing_rate", "the galerkin variant is stable without a filter and its kernel is not "
                                              "the smoothing's; set it to 0");
}

// Neighbours, then the operator (eqs. (21)-(22), corrected rows for the consistent variant) and the
// mass (rho / alpha, eqs. (28)-(29), for the published one), in the members' order.
template <int D>
VeryWeakSphProblem<D>::VeryWeakSphProblem(const ParticleSet<D>& particles,
                                          const VeryWeakSphProblemSettings<D>& settings)
    : kernel_(checkedKernel(settings)),
      neighbours_(neighboursFor<D>(particles, *kernel_, settings)),
      method_(assemblyFor<D>(particles, neighbours_, *kernel_, settings)) {
  prescribeFaces(
      particles.physicalCount(), [&particles](Index a) { return particles.faceMask[static_cast<std::size_t>(a)]; },
      settings);
  if (onLattice(settings)) {
    buildLattice(checkedLatticeNodes<D>(particles, settings), settings);
    return;
  }
  const bool galerkin = settings.options.variant == VeryWeakSphVariant::Galerkin;
  const bool consistent = settings.options.variant == VeryWeakSphVariant::Consistent;
  if (!settings.keepOperatorMatrix) SparseMatrix().swap(method_.data.operatorMatrix);  // swap frees
  LinearSecondOrderSystem& system = method_.system;
  const VeryWeakSphData<D>& data = method_.data;
  const Material& material = settings.options.material;

  // dashpots (eqs. (31)-(32))
  const std::uint8_t transmitting = settings.transmittingFaces;
  if (transmitting != 0 && galerkin)
    // int_face W_a rho Z v on the particle's own dofs: symmetric positive semi-definite.
    system.setDamping(lumpedFacetDashpots<D>(data.facets, material, transmitting));
  else if (transmitting != 0 && consistent)
    // The dashpot tractions go through the corrected facet blocks, like every traction.
    system.setDamping(dashpotsThroughTractionMatrix<D>(data.tractionMatrix, data.facets, material, transmitting));
  else if (transmitting != 0)
    system.setDamping(assembleTransmittingDamping<D>(particles, neighbours_, *kernel_, data.facets, material,
                                                     transmitting, settings.dashpotLumping));

  // loads (eq. (19)): fixed vectors T t scaled by their time functions, whole faces first
  std::vector<Load> loads;
  for (const FaceTraction<D>& face : settings.faceTractions)
    loads.push_back({faceTractionLoad<D>(data, face.faces, face.traction), face.history});
  for (const PatchTraction<D>& patch : settings.patches) {
    if (galerkin) {  // the exact int_patch W_a t of the tent kernel (GalerkinLattice.hpp)
      const std::vector<Real> weights = patchTentWeights<D>(particles, patch.face, patch.centre, patch.halfWidths,
                                                            settings.spacing, settings.lower, settings.upper);
      loads.push_back({patchNodalForce<D>(weights, settings.spacing, patch.traction), patch.history});
      continue;
    }
    const std::vector<Real> weights = patchLoadWeights<D>(particles, patch.face, patch.centre, patch.halfWidths,
                                                          settings.spacing, settings.lower, settings.upper);
    const Vector t = patchFacetTractions<D>(data.facets, patch.face, weights, patch.traction);
    loads.push_back({data.tractionMatrix * t, patch.history});
  }
  if (!loads.empty())
    system.setForce([loads = std::move(loads)](Real t, Vector& f) {
      for (const Load& load : loads) {
        const Real scale = (*load.history)(t);
        if (scale != 0) f.noalias() += scale * load.force;
      }
    });

  // the smoothing filter (eq. (33)) and the deconvolution (eq. (35))
  if (settings.smoothingRate > 0)
    smoothing_ = std::make_unique<ConservativeSmoothing>(
        smoothingMatrix<D>(particles, neighbours_, *kernel_, data.volume), D, settings.smoothingRate,
        settings.smoothingOrder);
  if (settings.deconvolution) deconvolution_ = deconvolutionMatrix<D>(particles, neighbours_, *kernel_, data.volume);
}

template <int D>
VeryWeakSphProblem<D>::VeryWeakSphProblem(const VeryWeakSphProblemSettings<D>& settings)
    : kernel_(checkedKernel(settings)),
      method_{VeryWeakSphData<D>{}, LinearSecondOrderSystem(SparseMatrix(), SparseMatrix(), SparseMatrix())} {
  if (!onLattice(settings))
    throw InputError("method.operator", "a problem set up without its particles needs the lattice storage");
  const std::array<Index, D> nodes = latticeNodesOf<D>(settings);
  std::array<Index, D> intervals = nodes;
  for (Index& n : intervals) --n;
  // The face tags makeLattice gives node a.
  const LatticeRowTypes<D> lattice(nodes, 1);
  prescribeFaces(
      lattice.nodeCount(), [&](Index a) { return latticeFaceMask<D>(intervals, lattice.node(a)); }, settings);
  buildLattice(nodes, settings);
}

// Prescribed displacements (eq. (30)), face by face, particle by particle, component by component;
// `faceMask(a)` is particle a's faceBit mask.
template <int D>
void VeryWeakSphProblem<D>::prescribeFaces(Index count, const std::function<std::uint8_t(Index)>& faceMask,
                                           const VeryWeakSphProblemSettings<D>& settings) {
  for (const PrescribedFaces<D>& faces : settings.prescribed)
    for (Index a = 0; a < count; ++a) {
      if ((faceMask(a) & faces.faces) == 0) continue;
      for (int c = 0; c < D; ++c) {
        prescribedDofs_.push_back(D * a + c);
        prescribedValue_.push_back(faces.value[c]);
        prescribedHistory_.push_back(faces.history);
      }
    }
}

template <int D>
void VeryWeakSphProblem<D>::buildLattice(const std::array<Index, D>& nodes,
                                         const VeryWeakSphProblemSettings<D>& settings) {
  const VeryWeakSphVariant variant = settings.options.variant;
  VeryWeakSphStencils<D> stencils = veryWeakSphStencils<D>(settings, nodes);
  latticeDepth_ = stencils.stiffness.types().depth();
  latticeMismatch_ = stencils.mismatch;

  // loads (eq. (19)): whole faces from their per-type forces, then patches, as nonzeros
  std::vector<SparseLoad> loads;
  const LatticeRowTypes<D>& types = stencils.stiffness.types();
  const Index nodeCount = types.nodeCount();
  for (std::size_t i = 0; i < settings.faceTractions.size(); ++i) {
    const std::vector<Real>& perType = stencils.faceLoads[i];
    SparseLoad load{{}, {}, settings.faceTractions[i].history};
    for (Index p = 0; p < types.nodeCount(); ++p) {
      const Index type = types.typeOf(types.node(p));
      for (int c = 0; c < D; ++c) {
        const Real value = perType[static_cast<std::size_t>(D * type + c)];
        if (value == 0) continue;
        load.dofs.push_back(D * p + c);
        load.values.push_back(value);
      }
    }
    loads.push_back(std::move(load));
  }
  // patches, from their neighbourhoods alone (LatticePatchLoad.hpp)
  for (const PatchTraction<D>& patch : settings.patches) {
    const bool kernelLoad = variant != VeryWeakSphVariant::Galerkin && patch.face >= 0 && patch.face < 2 * D;
    const LatticeStencils<D>* face = kernelLoad ? &stencils.patchFaces[static_cast<std::size_t>(patch.face)] : nullptr;
    loads.push_back(latticePatchLoad<D>(settings, patch, nodes, face));
  }
  for (const SparseLoad& load : loads)
    loadBytes_ += load.dofs.size() * (sizeof(Index) + sizeof(Real));
  lattice_ = std::make_unique<LatticeSecondOrderSystem<D>>(std::move(stencils.mass), std::move(stencils.damping),
                                                           std::move(stencils.stiffness), std::move(loads));
  if (settings.deconvolution)
    deconvolutionStencils_ = std::make_unique<LatticeStencils<D>>(std::move(stencils.deconvolution));
  // the smoothing filter (eq. (33)) from its stencils
  if (settings.smoothingRate > 0) {
    auto s = std::make_shared<const LatticeStencils<D>>(std::move(stencils.smoothing));
    smoothingStencils_ = s;
    smoothingBytes_ = s->bytes();
    smoothing_ = std::make_unique<ConservativeSmoothing>([s](const Vector& in, Vector& out) { s->multiply(in, out); },
                                                         nodeCount, D, settings.smoothingRate,
                                                         settings.smoothingOrder);
  }
}

template <int D>
ParticleMatrix VeryWeakSphProblem<D>::deconvolutionRows(const std::vector<Index>& particles,
                                                        const std::vector<int>& components) const {
  const Index n = system().size() / D;
  if (components.size() != particles.size())
    throw InputError("probe", "deconvolution rows need one component per particle");
  std::vector<Eigen::Triplet<Real, int>> entries;
  for (std::size_t k = 0; k < particles.size(); ++k) {
    const Index p = particles[k];
    const auto row = static_cast<int>(k);
    if (p < 0 || p >= n) throw InputError("particle", "particle " + std::to_string(p) + " is not a physical particle");
    if (deconvolution_) {
      for (ParticleMatrix::InnerIterator it(*deconvolution_, p); it; ++it)
        entries.emplace_back(row, static_cast<int>(it.col()), it.value());
    } else if (deconvolutionStencils_) {  // a diagonal block per entry: the component's own
      const LatticeStencils<D>& s = *deconvolutionStencils_;
      const Index type = s.types().typeOf(s.types().node(p));
      const int c = components[k];
      if (c < 0 || c >= D) throw InputError("probe", "component " + std::to_string(c) + " does not exist");
      for (Index e = s.begin(type); e < s.end(type); ++e)
        if (s.block(e)[D * c + c] != 0) entries.emplace_back(row, static_cast<int>(s.column(e, p)), s.block(e)[D * c + c]);
    }
  }
  ParticleMatrix rows(static_cast<Index>(particles.size()), n);
  rows.setFromTriplets(entries.begin(), entries.end());
  return rows;
}

template <int D>
LinearSecondOrderSystem& VeryWeakSphProblem<D>::sparseSystem() {
  if (lattice_)
    throw InputError("method.operator", "the problem is stored as lattice stencils; the assembled matrices need "
                                        "method.operator = \"sparse\"");
  return method_.system;
}

template <int D>
Real VeryWeakSphProblem<D>::meanStencilSize() const {
  if (!lattice_) return neighbours_.meanCount();
  const LatticeStencils<D>& k = lattice_->stiffness();
  return sumOverLatticeNodes<D>(k.types(), [&](Index, Index type) { return static_cast<Real>(k.end(type) - k.begin(type)); }) /
         static_cast<Real>(k.types().nodeCount());
}

template <int D>
Index VeryWeakSphProblem<D>::storedStiffnessEntries() const {
  return lattice_ ? D * D * lattice_->stiffness().entryCount() : method_.system.stiffness().nonZeros();
}

template <int D>
void VeryWeakSphProblem<D>::prescribedValues(Real t, Vector& values) const {
  for (std::size_t i = 0; i < prescribedDofs_.size(); ++i)
    values[static_cast<Index>(i)] = prescribedHistory_[i] ? prescribedValue_[i] * (*prescribedHistory_[i])(t) : 0;
}

template <int D>
Vector VeryWeakSphProblem<D>::initialDisplacement() const {
  Vector u0 = Vector::Zero(system().size());
  Vector g0(static_cast<Index>(prescribedDofs_.size()));
  prescribedValues(0, g0);
  for (std::size_t i = 0; i < prescribedDofs_.size(); ++i) u0[prescribedDofs_[i]] = g0[static_cast<Index>(i)];
  return u0;
}

template <int D>
Real VeryWeakSphProblem<D>::operatorMiB() const {
  if (lattice_)
    return static_cast<Real>(lattice_->bytes() + loadBytes_ + smoothingBytes_ +
                             (deconvolutionStencils_ ? deconvolutionStencils_->bytes() : 0)) /
           (1024.0 * 1024.0);
  const LinearSecondOrderSystem& s = method_.system;
  return compressedRowsMiB(s.stiffness()) + compressedRowsMiB(method_.data.tractionMatrix) +
         compressedRowsMiB(s.damping()) + compressedRowsMiB(s.mass());
}

template class VeryWeakSphProblem<1>;
template class VeryWeakSphProblem<2>;
template class VeryWeakSphProblem<3>;

}  // namespace mfwave
