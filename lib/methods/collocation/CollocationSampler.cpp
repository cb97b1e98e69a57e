#include "methods/collocation/CollocationSampler.hpp"

#include <algorithm>

namespace mfwave {

CollocationSampler::CollocationSampler(const ConstrainedCollocationSystem& system, const Eigen::MatrixXd& functionals)
    : system_(system), adjoint_(system.constraintAdjoint(functionals)) {}

std::vector<Real> CollocationSampler::sample(Real t, const Vector& U, const Vector& V, const std::vector<bool>& rate) const {
  const bool anyRate = std::find(rate.begin(), rate.end(), true) != rate.end();
  const bool anyValue = std::find(rate.begin(), rate.end(), false) != rate.end();
  const Vector data = anyValue ? system_.boundaryData(t) : Vector();
  const Vector dataRate = anyRate ? system_.boundaryDataRate(t, 1) : Vector();
  const Index interior = system_.size();
  std::vector<Real> out(static_cast<std::size_t>(adjoint_.cols()));
  for (Index i = 0; i < adjoint_.cols(); ++i) {
    const bool r = rate[static_cast<std::size_t>(i)];
    const auto g = adjoint_.col(i);
    out[static_cast<std::size_t>(i)] = g.head(interior).dot(r ? V : U) + g.tail(g.size() - interior).dot(r ? dataRate : data);
  }
  return out;
}

}  // namespace mfwave
