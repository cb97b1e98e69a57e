#include "methods/updated_lagrangian_sph/PairTable.hpp"

#include "kernels/KernelProfiles.hpp"
#include "methods/updated_lagrangian_sph/ArtificialStress.hpp"
#include "methods/updated_lagrangian_sph/ParallelThreshold.hpp"

#include <algorithm>
#include <cmath>

namespace mfwave {

namespace {

template <int D, class K>
void fillRows(const K& kernel, const NeighbourList& list, const Real* x, Index count,
              const PairTableSettings& settings, PairTable& table) {
  const Real support2 = kernel.supportRadius2();
  const Index* offsets = list.offsets.data();
  const Index* indices = list.indices.data();
  std::uint8_t* inside = table.inside.data();
  Real* factor = table.gradientFactor.data();
  Real* smoothing = settings.xsph ? table.smoothingWeight.data() : nullptr;
  Real* stress = settings.artificialStress ? table.stressWeight.data() : nullptr;
  const Real* rho = settings.rho;
  const Index* first = table.first.data();
  const Index* rows = table.offsets.data();
  // Row i evaluates its pairs with j > i (the tail of its sorted row) and writes only its entries.
#pragma omp parallel for if (count > kParallelParticles) schedule(static)
  for (Index i = 0; i < count; ++i) {
    const Vec<D> xi = Eigen::Map<const Vec<D>>(x + i * D);
    const Index end = offsets[i + 1];
    for (Index k = first[i], e = rows[i]; k < end; ++k, ++e) {
      const Index j = indices[k];
      const Vec<D> r = xi - Eigen::Map<const Vec<D>>(x + j * D);
      const Real r2 = r.squaredNorm();
      if (r2 >= support2) {  // listed through the skin but outside the support
        inside[e] = 0;
        continue;
      }
      const Real distance = std::sqrt(r2);
      inside[e] = 1;
      factor[e] = kernel.gradientFactorAt(distance);
      if (smoothing != nullptr || stress != nullptr) {
        const Real w = kernel.valueAt(distance);
        if (smoothing != nullptr) smoothing[e] = 2 * w / (rho[i] + rho[j]);
        if (stress != nullptr)
          stress[e] = artificialStressWeight(w, settings.inverseReferenceKernel, settings.artificialStressExponent);
      }
    }
  }
}

}  // namespace

template <int D>
void buildPairTable(const Kernel& kernel, const NeighbourList& list, const Real* x, Index count,
                    const PairTableSettings& settings, PairTable& table) {
  // The tail j > i of each sorted row and its place in the table, once per rebuild of the lists.
  const auto rowCount = static_cast<std::size_t>(count);
  if (!table.rowsValid || table.first.size() != rowCount) {
    table.first.resize(rowCount);
    table.offsets.resize(rowCount + 1);
    const Index* offsets = list.offsets.data();
    const Index* indices = list.indices.data();
    table.offsets[0] = 0;
    Index reach = 0;
    for (std::size_t i = 0; i < rowCount; ++i) {
      if (offsets[i + 1] > offsets[i]) reach = std::max(reach, indices[offsets[i + 1] - 1] - static_cast<Index>(i));
      const Index* end = indices + offsets[i + 1];
      const Index first =
          static_cast<Index>(std::upper_bound(indices + offsets[i], end, static_cast<Index>(i)) - indices);
      table.first[i] = first;
      table.offsets[i + 1] = table.offsets[i] + (offsets[i + 1] - first);
    }
    table.blockSize = std::max<Index>(reach, 64);
    table.rowsValid = true;
  }
  const auto entries = static_cast<std::size_t>(table.offsets[rowCount]);
  table.inside.resize(entries);
  table.gradientFactor.resize(entries);
  table.smoothingWeight.resize(settings.xsph ? entries : 0);
  table.stressWeight.resize(settings.artificialStress ? entries : 0);
  visitInlineKernel(kernel, [&](const auto& inlined) { fillRows<D>(inlined, list, x, count, settings, table); });
}

template void buildPairTable<1>(const Kernel&, const NeighbourList&, const Real*, Index, const PairTableSettings&,
                                PairTable&);
template void buildPairTable<2>(const Kernel&, const NeighbourList&, const Real*, Index, const PairTableSettings&,
                                PairTable&);
template void buildPairTable<3>(const Kernel&, const NeighbourList&, const Real*, Index, const PairTableSettings&,
                                PairTable&);

}  // namespace mfwave
