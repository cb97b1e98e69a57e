#include "methods/very_weak_sph/ConservativeSmoothing.hpp"

#include "core/Error.hpp"
#include "methods/very_weak_sph/StatisticalVolume.hpp"

#include <cmath>
#include <string>
#include <utility>

namespace mfwave {

template <int D>
ParticleMatrix smoothingMatrix(const ParticleSet<D>& particles, const NeighbourList& neighbours,
                               const Kernel& kernel, const std::vector<Real>& volumes) {
  checkVeryWeakInputs(particles, neighbours, kernel);
  const Index n = particles.physicalCount();
  if (static_cast<Index>(volumes.size()) != n) throw InputError("volumes", "need one volume per physical particle");
  // Row layout first (physical neighbours only; rows are sorted, so the columns come out sorted).
  std::vector<int> outer(static_cast<std::size_t>(n) + 1, 0);
  for (Index a = 0; a < n; ++a) {
    int count = 0;
    for (Index b : neighbours.row(a))
      if (b < n) ++count;
    outer[static_cast<std::size_t>(a) + 1] = outer[static_cast<std::size_t>(a)] + count;
  }
  const int nonZeros = outer.back();
  std::vector<int> inner(static_cast<std::size_t>(nonZeros));
  std::vector<Real> values(static_cast<std::size_t>(nonZeros));

#pragma omp parallel for schedule(dynamic, 64)
  for (Index a = 0; a < n; ++a) {
    const Vec<D> xa = particles.position(a);
    const auto first = static_cast<std::size_t>(outer[static_cast<std::size_t>(a)]);
    std::size_t s = first;
    Real sum = 0;
    for (Index b : neighbours.row(a)) {
      if (b >= n) continue;  // ghosts complete V only; they carry no velocity
      const Real weight = kernel.value(Vec<D>(xa - particles.position(b))) * volumes[static_cast<std::size_t>(b)];
      inner[s] = static_cast<int>(b);
      values[s] = weight;
      sum += weight;
      ++s;
    }
    // Ding-Long-Wu eq. (33): the kernel estimate normalised by sum_b W_ab V_b (= 1 / alpha_a).
    for (std::size_t k = first; k < s; ++k) values[k] /= sum;
  }
  const Eigen::Map<const ParticleMatrix> map(static_cast<int>(n), static_cast<int>(n), nonZeros, outer.data(),
                                             inner.data(), values.data());
  return ParticleMatrix(map);
}

void multiplyComponents(const ParticleMatrix& matrix, const Vector& in, int dimension, Vector& out) {
  const Index n = matrix.rows();
  if (in.size() != dimension * static_cast<Index>(matrix.cols()))
    throw InputError("field", "need " + std::to_string(dimension) + " components per particle (" +
                                  std::to_string(dimension * static_cast<Index>(matrix.cols())) + " entries), got " +
                                  std::to_string(in.size()));
  out.resize(dimension * n);
  const int* outer = matrix.outerIndexPtr();
  const int* inner = matrix.innerIndexPtr();
  const Real* values = matrix.valuePtr();
#pragma omp parallel for schedule(static) if (n > 4096)  // small sets: thread start-up costs more than the loop
  for (Index a = 0; a < n; ++a) {
    for (int c = 0; c < dimension; ++c) {
      Real sum = 0;
      for (int k = outer[a]; k < outer[a + 1]; ++k) sum += values[k] * in[dimension * static_cast<Index>(inner[k]) + c];
      out[dimension * a + c] = sum;
    }
  }
}

namespace {

void checkRate(Real rate) {
  if (!(rate >= 0) || !std::isfinite(rate))
    throw InputError("smoothing.rate", "must be >= 0 and finite (a damping rate per unit time), got " +
                                           std::to_string(rate));
}

void checkStep(Real dt) {
  if (!(dt > 0) || !std::isfinite(dt)) throw InputError("time_step", "must be > 0, got " + std::to_string(dt));
}

}  // namespace

ConservativeSmoothing::ConservativeSmoothing(ParticleMatrix matrix, int dimension, Real rate, int order)
    : matrix_(std::move(matrix)), particles_(matrix_.rows()), dimension_(dimension), rate_(rate), order_(order) {
  checkRate(rate);
  if (order != 1 && order != 2) throw InputError("smoothing.order", "must be 1 (eq. 33) or 2, got " + std::to_string(order));
  if (dimension < 1 || dimension > 3) throw InputError("dimension", "must be 1, 2 or 3");
  if (matrix_.rows() != matrix_.cols()) throw InputError("smoothing.matrix", "must be square (N x N)");
  matrix_.makeCompressed();
}

ConservativeSmoothing::ConservativeSmoothing(ComponentProduct product, Index particles, int dimension, Real rate,
                                             int order)
    : product_(std::move(product)), particles_(particles), dimension_(dimension), rate_(rate), order_(order) {
  checkRate(rate);
  if (order != 1 && order != 2) throw InputError("smoothing.order", "must be 1 (eq. 33) or 2, got " + std::to_string(order));
  if (dimension < 1 || dimension > 3) throw InputError("dimension", "must be 1, 2 or 3");
  if (!product_) throw InputError("smoothing.matrix", "the product of S is empty");
}

void ConservativeSmoothing::multiply(const Vector& in, Vector& out) const {
  if (product_) product_(in, out);
  else multiplyComponents(matrix_, in, dimension_, out);
}

Real ConservativeSmoothing::stepFraction(Real rate, Real dt) {
  checkRate(rate);
  checkStep(dt);
  return -std::expm1(-rate * dt);
}

Real ConservativeSmoothing::rateFromStepFraction(Real alpha, Real dt) {
  if (!(alpha >= 0) || !(alpha < 1))
    throw InputError("smoothing.alpha", "the fraction per step must be in [0, 1), got " + std::to_string(alpha));
  checkStep(dt);
  return -std::log1p(-alpha) / dt;
}

void ConservativeSmoothing::apply(Real dt, Vector& velocity) const {
  checkStep(dt);
  if (velocity.size() != dimension_ * particles_)
    throw InputError("velocity", "need " + std::to_string(dimension_) + " components per particle");
  if (rate_ == 0) return;
  const Real alpha = stepFraction(rate_, dt);
  multiply(velocity, work_);
  if (order_ == 1) {
    // Ding-Long-Wu eq. (33) with alpha = 1 - exp(-rate dt).
    velocity += alpha * (work_ - velocity);
    return;
  }
  // Order 2: d = (I - S) v, v <- v - alpha (I - S) d.
  difference_ = velocity - work_;
  multiply(difference_, work_);
  velocity -= alpha * (difference_ - work_);
}

template ParticleMatrix smoothingMatrix<1>(const ParticleSet<1>&, const NeighbourList&, const Kernel&,
                                           const std::vector<Real>&);
template ParticleMatrix smoothingMatrix<2>(const ParticleSet<2>&, const NeighbourList&, const Kernel&,
                                           const std::vector<Real>&);
template ParticleMatrix smoothingMatrix<3>(const ParticleSet<3>&, const NeighbourList&, const Kernel&,
                                           const std::vector<Real>&);

}  // namespace mfwave
