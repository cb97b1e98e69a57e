#pragma once
// Shows the state of the updated-Lagrangian SPH to the ordinary particle observers.
//
// A first-order integrator hands its observers the whole state y (positions, densities, stresses,
// velocities, energies: UpdatedLagrangianSphLayout). The VTK and PNG frame writers and the probe
// recorder expect particles at their current positions and a displacement / velocity pair of D
// components per particle. This adapter is an Observer that, each time it is called, moves a
// particle set to the positions in y, forms u = x - X and v, and forwards that view to the
// observers added to it. `extraFields()` adds density, pressure, the Cauchy stress and the specific
// internal energy to every frame.

#include "io/vtk/StateFrame.hpp"
#include "methods/updated_lagrangian_sph/UpdatedLagrangianSph.hpp"
#include "observers/Observer.hpp"
#include "particles/ParticleSet.hpp"

#include <vector>

namespace mfwave {

template <int D>
class SolidStateAdapter : public Observer {
 public:
  // `particles` is the set the system was built from; the adapter keeps its own copy, whose
  // positions it updates (particles() is what frame writers must be given).
  SolidStateAdapter(const UpdatedLagrangianSph<D>& system, const ParticleSet<D>& particles);

  // Observers that see the adapted view; they must outlive the adapter's use.
  void add(Observer& observer) { observers_.push_back(&observer); }
  const ParticleSet<D>& particles() const { return moved_; }

  void begin(const StateView& state) override;
  void observe(const StateView& state) override;
  void end(const StateView& state) override;

  // density, pressure, stress (Cauchy, symmetric tensor XX YY ZZ XY YZ XZ) and internal_energy of
  // the state last adapted.
  ExtraFields extraFields() const;

 private:
  StateView adapt(const StateView& state);

  const UpdatedLagrangianSph<D>& system_;
  ParticleSet<D> moved_;
  Coordinates<D> reference_;
  Vector displacement_;
  Vector velocity_;
  const Vector* lastState_ = nullptr;
  std::vector<Observer*> observers_;
};

extern template class SolidStateAdapter<1>;
extern template class SolidStateAdapter<2>;
extern template class SolidStateAdapter<3>;

}  // namespace mfwave
