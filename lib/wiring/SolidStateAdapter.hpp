#pragma once
// Shows the state of the updated-Lagrangian SPH to the ordinary particle observers.
//
// A first-order integrator hands its observers the whole state y (positions, densities, stresses,
// velocities, energies: UpdatedLagrangianSphLayout). The VTK and PNG frame writers and the probe
// recorder expect particles at their current positions and a displacement / velocity pair of D
// components per particle. This adapter (a ViewAdapter: each observer at its own interval, the
// view formed only when one is due) moves its particle set to the positions in y, forms u = x - X
// and v, and forwards that view. One adapter serves every particle output of a run.
// `extraFields()` adds density, pressure, the Cauchy stress and the specific internal energy to
// every frame.

#include "io/vtk/StateFrame.hpp"
#include "methods/updated_lagrangian_sph/UpdatedLagrangianSph.hpp"
#include "observers/ViewAdapter.hpp"
#include "particles/ParticleSet.hpp"


namespace mfwave {

template <int D>
class SolidStateAdapter : public ViewAdapter {
 public:
  // `particles` is the set the system was built from; the adapter keeps its own copy, whose
  // positions it updates (particles() is what frame writers must be given).
  SolidStateAdapter(const UpdatedLagrangianSph<D>& system, const ParticleSet<D>& particles);

  const ParticleSet<D>& particles() const { return moved_; }

  // density, pressure, stress (Cauchy, symmetric tensor XX YY ZZ XY YZ XZ) and internal_energy of
  // the state last adapted.
  ExtraFields extraFields() const;

 private:
  StateView adapt(const StateView& state) override;

  const UpdatedLagrangianSph<D>& system_;
  ParticleSet<D> moved_;
  Coordinates<D> reference_;
  Vector displacement_;
  Vector velocity_;
  const Vector* lastState_ = nullptr;
};

extern template class SolidStateAdapter<1>;
extern template class SolidStateAdapter<2>;
extern template class SolidStateAdapter<3>;

}  // namespace mfwave
