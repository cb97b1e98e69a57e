#pragma once
// The whole very weak form SPH set-up of one run behind one call: kernel, neighbours, assembly
// (VeryWeakSph.hpp), transmitting dashpots chosen by variant (eqs. (31)-(32)), traction loads on
// whole faces and on surface patches (eq. (19)), prescribed displacement dofs (eq. (30)), the
// conservative smoothing filter (eq. (33)) and the deconvolution of reported values (eq. (35)).
// A driver describes the problem (faces, loads, switches) and wires the result to an integrator
// and observers; it never touches the method's matrices.
//
// The description holds plain values, not scene types, so that the method stays below the scene
// reader; lib/wiring/VeryWeakSphScene turns a scene into it.

#include "core/TimeFunction.hpp"
#include "core/Types.hpp"
#include "kernels/Kernel.hpp"
#include "lattice/LatticeSecondOrderSystem.hpp"
#include "methods/very_weak_sph/ConservativeSmoothing.hpp"
#include "methods/very_weak_sph/TransmittingBoundary.hpp"
#include "methods/very_weak_sph/VeryWeakSph.hpp"
#include "neighbours/NeighbourList.hpp"
#include "particles/ParticleSet.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mfwave {

// A traction t(x, s) = traction * history(s) on every facet of the faces in `faces` (eq. (19)).
template <int D>
struct FaceTraction {
  std::uint8_t faces = 0;   // faceBit mask
  Vec<D> traction = Vec<D>::Zero();
  const TimeFunction* history = nullptr;  // must outlive the problem
};

// A traction on the part of one face within `halfWidths` of `centre` (PatchLoad.hpp).
template <int D>
struct PatchTraction {
  int face = 0;             // BoxFace index
  Vec<D> centre = Vec<D>::Zero();
  Vec<D> halfWidths = Vec<D>::Zero();
  Vec<D> traction = Vec<D>::Zero();
  const TimeFunction* history = nullptr;  // must outlive the problem
};

// Every component of the particles on `faces` held at value * history(t) (eq. (30)); without a
// history the face is fixed at zero.
template <int D>
struct PrescribedFaces {
  std::uint8_t faces = 0;
  Vec<D> value = Vec<D>::Zero();
  const TimeFunction* history = nullptr;
};

// How the step's operators are stored: as assembled sparse matrices (any particle set; the
// reference) or as per-row-type stencils on the box lattice (VeryWeakSphLattice.hpp: nothing per
// particle, the same rows).
enum class OperatorStorage { Sparse, Lattice };

template <int D>
struct VeryWeakSphProblemSettings {
  VeryWeakSphOptions options;            // variant, material, the boundary corrections
  std::string kernel = "cubic_spline";   // kernelNames()
  Real smoothingLength = 0;              // h
  // The lattice box and spacing the particles were built on (patch weights are exact on it).
  Vec<D> lower = Vec<D>::Zero(), upper = Vec<D>::Zero();
  Real spacing = 0;
  // The ghost layers the particles were built with (the lattice storage rebuilds them on its
  // compact lattices).
  int ghostLayers = 0;
  std::uint8_t ghostFaces = 0;
  OperatorStorage storage = OperatorStorage::Sparse;
  // Dashpots on these faces: lumped facet dashpots for the galerkin variant, through the corrected
  // traction matrix for the consistent one, eq. (32) with `dashpotLumping` for the published one.
  std::uint8_t transmittingFaces = 0;
  // Symmetry planes on these faces (at most one per axis): the box is one side of a mirror-symmetric
  // solid, loaded symmetrically (lattice/SymmetryFold.hpp). The lattice storage only.
  std::uint8_t symmetryFaces = 0;
  DashpotLumping dashpotLumping = DashpotLumping::Particle;
  std::vector<FaceTraction<D>> faceTractions;
  std::vector<PatchTraction<D>> patches;
  std::vector<PrescribedFaces<D>> prescribed;
  Real smoothingRate = 0;                // 1/s; 0: no filter (eq. (33))
  int smoothingOrder = 1;
  bool deconvolution = false;            // build the matrix of eq. (35) for reported values
  // The assembled K is kept in data().operatorMatrix only when asked: the system holds -K already.
  bool keepOperatorMatrix = false;
};

// Eq. (19) for a traction on whole faces: the nodal force T t with t = traction on every facet of
// the faces in `faces` (a faceBit mask).
template <int D>
Vector faceTractionLoad(const VeryWeakSphData<D>& data, std::uint8_t faces, const Vec<D>& traction);

// Throws InputError for what the method cannot combine: deconvolution ("method.deconvolution") or
// the smoothing filter ("method.smoothing_rate") with the galerkin variant, whose state is nodal and
// stable without a filter. Drivers call it when the scene is read; the problem calls it again.
void checkVeryWeakSphCombination(VeryWeakSphVariant variant, bool deconvolution, Real smoothingRate);

template <int D>
class VeryWeakSphProblem {
 public:
  // Assembles everything the settings ask for. The particle set must outlive the problem. Throws
  // what checkVeryWeakSphCombination and assembleVeryWeakSph throw.
  VeryWeakSphProblem(const ParticleSet<D>& particles, const VeryWeakSphProblemSettings<D>& settings);
  // The lattice storage set up from the lattice's description alone, without its particles (what
  // a rank of a split run builds, issue 22): the stencils, loads and filter the lattice's particles
  // give, entry for entry (prescribed faces from the lattice's face tags). Throws
  // InputError("method.operator") unless settings.storage is Lattice.
  explicit VeryWeakSphProblem(const VeryWeakSphProblemSettings<D>& settings);

  // The system to step: the sparse one, or the lattice one with settings.storage = Lattice.
  LinearOperatorSystem& system() { return lattice_ ? static_cast<LinearOperatorSystem&>(*lattice_) : method_.system; }
  const LinearOperatorSystem& system() const {
    return lattice_ ? static_cast<const LinearOperatorSystem&>(*lattice_) : method_.system;
  }
  bool latticeStorage() const { return static_cast<bool>(lattice_); }
  // The assembled matrices; throws InputError("method.operator") with the lattice storage.
  LinearSecondOrderSystem& sparseSystem();
  const LatticeSecondOrderSystem<D>* latticeSystem() const { return lattice_.get(); }
  // Method data (volumes, facets, T); empty with the lattice storage.
  const VeryWeakSphData<D>& data() const { return method_.data; }
  const Kernel& kernel() const { return *kernel_; }
  // Empty with the lattice storage (it addresses neighbours by lattice arithmetic).
  const NeighbourList& neighbours() const { return neighbours_; }
  // Mean number of stiffness blocks per row (neighbours coupled, itself included).
  Real meanStencilSize() const;
  // Stored stiffness entries: the sparse matrix's nonzeros, or the stencil table's.
  Index storedStiffnessEntries() const;
  // The row-type depth of the lattice storage (0 for sparse) and how far its stencils are from an
  // assembly on a larger lattice (relative, 0 for sparse).
  Index latticeDepth() const { return latticeDepth_; }
  Real latticeMismatch() const { return latticeMismatch_; }

  // Eq. (30): the prescribed dofs (particle * D + component) and their values at time t, in that
  // order; the displacement at rest with the prescribed dofs at their values at t = 0.
  const std::vector<Index>& prescribedDofs() const { return prescribedDofs_; }
  void prescribedValues(Real t, Vector& values) const;
  Vector initialDisplacement() const;

  // Eq. (33) when settings.smoothingRate > 0, else null. The caller applies it as the
  // integrator's velocity filter.
  ConservativeSmoothing* smoothing() { return smoothing_.get(); }
  // S of the smoothing as lattice stencils (the lattice storage with a filter), else null: what a
  // run on ranks applies to its share (lib/decomposition).
  const LatticeStencils<D>* smoothingStencils() const { return smoothingStencils_.get(); }
  // Eq. (35) when settings.deconvolution with the sparse storage, else null.
  const ParticleMatrix* deconvolution() const { return deconvolution_ ? &*deconvolution_ : nullptr; }
  // Whether eq. (35) is on (either storage), and its rows at `particles`: a P x N matrix whose row k
  // is particles[k]'s for displacement component components[k] (what probes read, nothing
  // whole-lattice sized; empty rows when it is off). The rows are the same for every component but
  // near symmetry planes, where the reflection flips the normal component's images.
  bool deconvolves() const { return deconvolution_.has_value() || deconvolutionStencils_ != nullptr; }
  ParticleMatrix deconvolutionRows(const std::vector<Index>& particles, const std::vector<int>& components) const;

  // Storage of the step's operators, MiB: the matrices (stiffness, traction, damping, mass) in
  // compressed rows, or the stencil tables and the loads' nonzeros.
  Real operatorMiB() const;

 private:
  struct Load {
    Vector force;  // T t for the unit history
    const TimeFunction* history;
  };

  void prescribeFaces(Index count, const std::function<std::uint8_t(Index)>& faceMask,
                      const VeryWeakSphProblemSettings<D>& settings);
  // The lattice storage: stencils from compact assemblies, loads as nonzeros.
  void buildLattice(const std::array<Index, D>& nodes, const VeryWeakSphProblemSettings<D>& settings);

  std::unique_ptr<Kernel> kernel_;
  NeighbourList neighbours_;
  VeryWeakSph<D> method_;
  std::unique_ptr<LatticeSecondOrderSystem<D>> lattice_;
  Index latticeDepth_ = 0;
  Real latticeMismatch_ = 0;
  std::size_t loadBytes_ = 0;
  std::size_t smoothingBytes_ = 0;
  std::vector<Index> prescribedDofs_;
  std::vector<Real> prescribedValue_;
  std::vector<const TimeFunction*> prescribedHistory_;
  std::unique_ptr<ConservativeSmoothing> smoothing_;
  std::shared_ptr<const LatticeStencils<D>> smoothingStencils_;  // shared with smoothing_'s product
  std::optional<ParticleMatrix> deconvolution_;
  std::unique_ptr<LatticeStencils<D>> deconvolutionStencils_;  // lattice storage with eq. (35)
};

extern template class VeryWeakSphProblem<1>;
extern template class VeryWeakSphProblem<2>;
extern template class VeryWeakSphProblem<3>;

}  // namespace mfwave
