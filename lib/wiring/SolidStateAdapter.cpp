#include "wiring/SolidStateAdapter.hpp"

namespace mfwave {

template <int D>
SolidStateAdapter<D>::SolidStateAdapter(const UpdatedLagrangianSph<D>& system, const ParticleSet<D>& particles)
    : system_(system), moved_(particles), reference_(particles.coordinates()) {
  const Index n = system.particleCount();
  displacement_ = Vector::Zero(n * D);
  velocity_ = Vector::Zero(n * D);
}

template <int D>
StateView SolidStateAdapter<D>::adapt(const StateView& state) {
  const auto& layout = system_.layout();
  const Vector& y = state.displacement;  // a first-order integrator's view: the whole state
  for (Index i = 0; i < layout.particles; ++i) {
    for (int a = 0; a < D; ++a) {
      const Real x = y[layout.position(i, a)];
      moved_.coordinate(a)[static_cast<std::size_t>(i)] = x;
      displacement_[i * D + a] = x - reference_[static_cast<std::size_t>(a)][static_cast<std::size_t>(i)];
      velocity_[i * D + a] = y[layout.velocity(i, a)];
    }
  }
  lastState_ = &y;
  return {state.step, state.time, displacement_, velocity_, state.dt};
}

template <int D>
ExtraFields SolidStateAdapter<D>::extraFields() const {
  return [this](const StateView&, Index count, std::vector<ParticleField>& fields) {
    if (lastState_ == nullptr) return;
    const Vector& y = *lastState_;
    std::vector<Real> density(static_cast<std::size_t>(count)), pressure(density.size()), energy(density.size());
    std::vector<Real> stress(6 * density.size(), 0.0);
    // VTK's symmetric tensor order XX YY ZZ XY YZ XZ
    constexpr int row[6] = {0, 1, 2, 0, 1, 0};
    constexpr int col[6] = {0, 1, 2, 1, 2, 2};
    for (Index i = 0; i < count; ++i) {
      const auto k = static_cast<std::size_t>(i);
      density[k] = system_.density(y, i);
      pressure[k] = system_.pressure(y, i);
      energy[k] = y[system_.layout().energy(i)];
      const Mat<D> sigma = system_.stress(y, i);
      for (int c = 0; c < 6; ++c)
        if (row[c] < D && col[c] < D) stress[6 * k + static_cast<std::size_t>(c)] = sigma(row[c], col[c]);
    }
    fields.push_back(ParticleField::scalar("density", std::move(density)));
    fields.push_back(ParticleField::scalar("pressure", std::move(pressure)));
    fields.push_back(ParticleField::tensor("stress", 6, std::move(stress)));
    fields.push_back(ParticleField::scalar("internal_energy", std::move(energy)));
  };
}

template class SolidStateAdapter<1>;
template class SolidStateAdapter<2>;
template class SolidStateAdapter<3>;

}  // namespace mfwave
