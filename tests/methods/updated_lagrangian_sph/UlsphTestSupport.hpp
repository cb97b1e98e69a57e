#pragma once
// Helpers for the updated-Lagrangian SPH tests: a lattice block, the particles whose kernel
// support lies wholly inside it, and a local kick-drift-kick leapfrog (the project's integrators
// live in lib/integrators; these tests do not depend on them).

#include "methods/updated_lagrangian_sph/UpdatedLagrangianSph.hpp"
#include "particles/Lattice.hpp"

#include <vector>

namespace mfwave::test {

// Particles of `particles` farther than `margin` from every face of [lower, upper].
template <int D>
std::vector<Index> interiorParticles(const ParticleSet<D>& particles, const Vec<D>& lower, const Vec<D>& upper,
                                     Real margin) {
  std::vector<Index> inside;
  for (Index i = 0; i < particles.size(); ++i) {
    const Vec<D> x = particles.position(i);
    bool ok = true;
    for (int a = 0; a < D; ++a) ok = ok && x[a] - lower[a] > margin && upper[a] - x[a] > margin;
    if (ok) inside.push_back(i);
  }
  return inside;
}

// Kick-drift-kick on y = [q; p] with the split rates, as the project's leapfrog
// (lib/integrators/SplitLeapfrog) does:
//   p_{n+1/2} = p_n + dt/2 P_n;  q_{n+1} = q_n + dt Q(t_n + dt/2, [q_n; p_{n+1/2}]);
//   p* = p_{n+1/2} + dt/2 P_n (predictor);  P_{n+1} = P(t_{n+1}, [q_{n+1}; p*]);
//   p_{n+1} = p_{n+1/2} + dt/2 P_{n+1}.
class LocalLeapfrog {
 public:
  LocalLeapfrog(SplitFirstOrderSystem& system, Vector y, Real t = 0)
      : system_(system), y_(std::move(y)), t_(t), nq_(system.configurationSize()) {
    pdot_.resize(system.size() - nq_);
    qdot_.resize(nq_);
    system_.momentumRate(t_, y_, pdot_);
  }
  void step(Real dt) {
    auto p = y_.tail(pdot_.size());
    const Vector half = p + 0.5 * dt * pdot_;
    p = half;
    system_.configurationRate(t_ + 0.5 * dt, y_, qdot_);
    y_.head(nq_) += dt * qdot_;
    p = half + 0.5 * dt * pdot_;
    t_ += dt;
    system_.momentumRate(t_, y_, pdot_);
    p = half + 0.5 * dt * pdot_;
  }
  const Vector& state() const { return y_; }
  Vector& state() { return y_; }
  Real time() const { return t_; }

 private:
  SplitFirstOrderSystem& system_;
  Vector y_;
  Real t_;
  Index nq_;
  Vector pdot_, qdot_;
};

}  // namespace mfwave::test
