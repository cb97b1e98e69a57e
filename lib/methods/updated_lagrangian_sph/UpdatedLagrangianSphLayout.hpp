#pragma once
// Where each field lives in the state vector y of the updated-Lagrangian SPH, for N particles in
// D dimensions with S = D (D + 1) / 2 independent deviatoric stress components:
//
//   q (configuration) = [ x: N D | rho: N | s: N S ]
//   p (momentum)      = [ v: N D | e: N | ledger: 3 ]
//
// Vector fields are particle-major (dof = i D + a), as everywhere in mfwave. The stress is stored
// in Voigt order: 1-D (xx); 2-D (xx, yy, xy); 3-D (xx, yy, zz, yz, xz, xy). In 2-D the out-of-plane
// component is s_zz = -(s_xx + s_yy) (s is traceless and plane strain keeps it so). The ledger holds
// the time integrals the energy balance needs: work done on the body by loads and constraints, energy
// removed by the artificial viscosity, and work of the artificial stress.

#include "core/Types.hpp"

namespace mfwave {

template <int D>
struct UpdatedLagrangianSphLayout {
  static constexpr int stressComponents = D * (D + 1) / 2;
  static constexpr Index ledgerEntries = 3;
  enum LedgerEntry : Index { LoadWork = 0, ViscousDissipation = 1, ArtificialStressWork = 2 };

  Index particles = 0;

  Index positionOffset() const { return 0; }
  Index densityOffset() const { return particles * D; }
  Index stressOffset() const { return particles * (D + 1); }
  Index configurationSize() const { return particles * (D + 1 + stressComponents); }
  Index velocityOffset() const { return configurationSize(); }
  Index energyOffset() const { return velocityOffset() + particles * D; }
  Index ledgerOffset() const { return energyOffset() + particles; }
  Index size() const { return ledgerOffset() + ledgerEntries; }

  Index position(Index i, int a) const { return positionOffset() + i * D + a; }
  Index density(Index i) const { return densityOffset() + i; }
  Index stress(Index i, int component) const { return stressOffset() + i * stressComponents + component; }
  Index velocity(Index i, int a) const { return velocityOffset() + i * D + a; }
  Index energy(Index i) const { return energyOffset() + i; }
  Index ledger(LedgerEntry entry) const { return ledgerOffset() + entry; }
};

}  // namespace mfwave
