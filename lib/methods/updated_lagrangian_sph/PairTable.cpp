#include "methods/updated_lagrangian_sph/PairTable.hpp"

#include "kernels/KernelProfiles.hpp"
#include "methods/updated_lagrangian_sph/ParallelThreshold.hpp"

#include <cmath>

namespace mfwave {

namespace {

template <int D>
Real squaredDistance(const Real* x, Index i, Index j) {
  const Vec<D> r = Eigen::Map<const Vec<D>>(x + i * D) - Eigen::Map<const Vec<D>>(x + j * D);
  return r.squaredNorm();
}

template <int D, class K>
void fillRows(const K& kernel, const NeighbourList& list, const Real* x, Index count, bool withValues,
              PairTable& table) {
  const Real support2 = kernel.supportRadius2();
  const Index* listOffsets = list.offsets.data();
  const Index* indices = list.indices.data();
  Index* offsets = table.offsets.data();
  // Count the pairs inside the support per row, then the row offsets (a serial scan).
#pragma omp parallel for if (count > kParallelParticles) schedule(static)
  for (Index i = 0; i < count; ++i) {
    Index inside = 0;
    for (Index e = listOffsets[i]; e < listOffsets[i + 1]; ++e) {
      const Index j = indices[e];
      inside += (j != i && squaredDistance<D>(x, i, j) < support2) ? 1 : 0;
    }
    offsets[i + 1] = inside;
  }
  offsets[0] = 0;
  for (Index i = 0; i < count; ++i) offsets[i + 1] += offsets[i];
  const auto entries = static_cast<std::size_t>(offsets[count]);
  table.neighbour.resize(entries);
  table.gradientFactor.resize(entries);
  table.value.resize(withValues ? entries : 0);
  Index* neighbour = table.neighbour.data();
  Real* factor = table.gradientFactor.data();
  Real* value = withValues ? table.value.data() : nullptr;
#pragma omp parallel for if (count > kParallelParticles) schedule(static)
  for (Index i = 0; i < count; ++i) {
    Index k = offsets[i];
    for (Index e = listOffsets[i]; e < listOffsets[i + 1]; ++e) {
      const Index j = indices[e];
      if (j == i) continue;
      const Real r2 = squaredDistance<D>(x, i, j);
      if (r2 >= support2) continue;  // listed through the skin but outside the support
      const Real distance = std::sqrt(r2);
      neighbour[k] = j;
      factor[k] = kernel.gradientFactorAt(distance);
      if (value != nullptr) value[k] = kernel.valueAt(distance);
      ++k;
    }
  }
}

}  // namespace

template <int D>
void buildPairTable(const Kernel& kernel, const NeighbourList& list, const Real* x, Index count, bool withValues,
                    PairTable& table) {
  table.offsets.resize(static_cast<std::size_t>(count) + 1);
  visitInlineKernel(kernel, [&](const auto& inlined) { fillRows<D>(inlined, list, x, count, withValues, table); });
}

template void buildPairTable<1>(const Kernel&, const NeighbourList&, const Real*, Index, bool, PairTable&);
template void buildPairTable<2>(const Kernel&, const NeighbourList&, const Real*, Index, bool, PairTable&);
template void buildPairTable<3>(const Kernel&, const NeighbourList&, const Real*, Index, bool, PairTable&);

}  // namespace mfwave
