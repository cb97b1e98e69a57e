#include "lattice/PeriodicStencilSystem.hpp"

#include "core/Error.hpp"
#include "lattice/StencilRun.hpp"

#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <string>

namespace mfwave {

template <int D, int C>
PeriodicStencilSystem<D, C>::PeriodicStencilSystem(int cells, const std::vector<std::array<int, D>>& steps,
                                                   const std::vector<Real>& blocks)
    : cells_(cells) {
  if (cells < 2 || cells % 2 != 0) throw InputError("cells", "must be even and at least 2, got " + std::to_string(cells));
  if (steps.empty()) throw InputError("stencil", "the stencil is empty");
  if (blocks.size() != static_cast<std::size_t>(C * C) * steps.size())
    throw InputError("stencil", std::to_string(blocks.size()) + " block values for " + std::to_string(steps.size()) +
                                    " offsets of " + std::to_string(C) + " x " + std::to_string(C) + " blocks");
  for (const auto& s : steps)
    for (int v : s) reach_ = std::max(reach_, std::abs(v));
  if (2 * reach_ >= cells)
    throw InputError("cells", std::to_string(cells) + " nodes per axis are too few for a stencil reaching " +
                                  std::to_string(reach_) + " spacings: need more than " + std::to_string(2 * reach_));
  // Entries ordered like node indices (z, then y, then x): stencilRun wants the entries of one
  // neighbouring line consecutive.
  std::vector<std::size_t> order(steps.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  auto before = [&](std::size_t a, std::size_t b) {
    for (int k = D - 1; k >= 0; --k)
      if (steps[a][static_cast<std::size_t>(k)] != steps[b][static_cast<std::size_t>(k)])
        return steps[a][static_cast<std::size_t>(k)] < steps[b][static_cast<std::size_t>(k)];
    return false;
  };
  std::stable_sort(order.begin(), order.end(), before);
  for (std::size_t k = 0; k < order.size(); ++k) {
    if (k > 0 && !before(order[k - 1], order[k])) throw InputError("stencil", "an offset is given twice");
    steps_.push_back(steps[order[k]]);
    dx_.push_back(steps[order[k]][0]);
    blocks_.insert(blocks_.end(), blocks.begin() + static_cast<std::ptrdiff_t>(C * C * order[k]),
                   blocks.begin() + static_cast<std::ptrdiff_t>(C * C * (order[k] + 1)));
  }
  nodes_ = 1;
  for (int d = 0; d < D; ++d) nodes_ *= cells;
  lines_ = nodes_ / cells;
  tableNumber_ = freshStencilNumbers(1);
}

template <int D, int C>
void PeriodicStencilSystem<D, C>::multiply(const Real* x, Real* y) const {
  const Index n = cells_, reach = reach_, length = n - 2 * reach;
  const auto entries = static_cast<Index>(steps_.size());
  const std::uint64_t pass = nextStencilProduct();
#pragma omp parallel for schedule(static) if (lines_ > 16 && nodes_ > 20000)
  for (long line = 0; line < static_cast<long>(lines_); ++line) {
    const Index first = static_cast<Index>(line) * n;
    // Per entry: where its neighbouring line starts, relative to this line, wrapped across the
    // periodic faces of the axes other than x.
    thread_local std::vector<Index> lineOffset, flat;
    lineOffset.resize(static_cast<std::size_t>(entries));
    flat.resize(static_cast<std::size_t>(entries));
    for (Index e = 0; e < entries; ++e) {
      Index rest = static_cast<Index>(line), start = 0, stride = n;
      for (int a = 1; a < D; ++a) {
        const Index at = rest % n;
        rest /= n;
        start += stride * ((at + steps_[static_cast<std::size_t>(e)][static_cast<std::size_t>(a)] + n) % n);
        stride *= n;
      }
      lineOffset[static_cast<std::size_t>(e)] = start - first;
      flat[static_cast<std::size_t>(e)] = start - first + dx_[static_cast<std::size_t>(e)];
    }
    // The ends of the line, x wrapped: each row summed like LatticeStencils::rowProduct.
    auto single = [&](Index i) {
      Real acc[C] = {};
      for (Index e = 0; e < entries; ++e) {
        const Real* b = &blocks_[static_cast<std::size_t>(C * C * e)];
        const Index column = first + lineOffset[static_cast<std::size_t>(e)] + (i + dx_[static_cast<std::size_t>(e)] + n) % n;
        const Real* xe = x + C * column;
        for (int c = 0; c < C; ++c)
          for (int d = 0; d < C; ++d) acc[c] += b[C * c + d] * xe[d];
      }
      for (int c = 0; c < C; ++c) y[C * (first + i) + c] = acc[c];
    };
    for (Index i = 0; i < reach; ++i) single(i);
    for (Index i = n - reach; i < n; ++i) single(i);
    thread_local StencilRunCache cache;
    thread_local std::vector<Real> run;
    if (run.size() < static_cast<std::size_t>(C * length)) run.resize(static_cast<std::size_t>(C * length));
    const StencilView view{blocks_.data(), flat.data(), dx_.data(), entries, tableNumber_};
    stencilRun<C>(view, x, first + reach, length, run.data(), cache, pass);
    for (Index l = 0; l < length; ++l)
      for (int c = 0; c < C; ++c) y[C * (first + reach + l) + c] = run[static_cast<std::size_t>(c * length + l)];
  }
}

template <int D, int C>
void PeriodicStencilSystem<D, C>::acceleration(Real, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector>,
                                               Eigen::Ref<Vector> a) {
  multiply(u.data(), a.data());
}

template <int D, int C>
void PeriodicStencilSystem<D, C>::force(Real, Vector& f) const {
  f.setZero(size());
}

template <int D, int C>
void PeriodicStencilSystem<D, C>::applyStiffness(const Vector& x, Vector& y) const {
  y.resize(size());
  multiply(x.data(), y.data());
  y = -y;  // K = -A
}

template <int D, int C>
Real PeriodicStencilSystem<D, C>::strainEnergy(const Vector& u) const {
  Vector au(size());
  multiply(u.data(), au.data());
  return -0.5 * u.dot(au);
}

template <int D, int C>
Vector PeriodicStencilSystem<D, C>::stiffnessAbsoluteRowSums() const {
  Real row[C] = {};
  for (std::size_t e = 0; e < steps_.size(); ++e)
    for (int c = 0; c < C; ++c)
      for (int d = 0; d < C; ++d) row[c] += std::abs(blocks_[C * C * e + static_cast<std::size_t>(C * c + d)]);
  Vector sums(size());
  for (Index p = 0; p < nodes_; ++p)
    for (int c = 0; c < C; ++c) sums[C * p + c] = row[c];
  return sums;
}

namespace {

// Without dampers eq. (32) is a = M^-1 (f - K u) = A u, with the prescribed dofs' known values.
template <int D, int C>
class PeriodicUndampedSolve : public CentredDampingSolve {
 public:
  PeriodicUndampedSolve(const PeriodicStencilSystem<D, C>& system, std::vector<Index> prescribed)
      : system_(system), prescribed_(std::move(prescribed)) {}
  void acceleration(Real, const Vector& u, const Vector&, const Vector& prescribedAcceleration, Vector& a) override {
    a.resize(system_.size());
    system_.multiply(u.data(), a.data());
    for (std::size_t k = 0; k < prescribed_.size(); ++k) a[prescribed_[k]] = prescribedAcceleration[static_cast<Index>(k)];
  }

 private:
  const PeriodicStencilSystem<D, C>& system_;
  std::vector<Index> prescribed_;
};

}  // namespace

template <int D, int C>
std::unique_ptr<CentredDampingSolve> PeriodicStencilSystem<D, C>::centredDamping(Real,
                                                                                 const std::vector<Index>& prescribedDofs) const {
  return std::make_unique<PeriodicUndampedSolve<D, C>>(*this, prescribedDofs);
}

template <int D, int C>
std::size_t PeriodicStencilSystem<D, C>::bytes() const {
  return steps_.size() * sizeof(std::array<int, D>) + blocks_.size() * sizeof(Real) + dx_.size() * sizeof(Index);
}

template class PeriodicStencilSystem<1, 1>;
template class PeriodicStencilSystem<2, 1>;
template class PeriodicStencilSystem<2, 2>;
template class PeriodicStencilSystem<3, 1>;
template class PeriodicStencilSystem<3, 3>;

}  // namespace mfwave
