#include "methods/updated_lagrangian_sph/PairTable.hpp"

#include "core/Error.hpp"
#include "kernels/KernelProfiles.hpp"
#include "methods/updated_lagrangian_sph/ArtificialStress.hpp"
#include "methods/updated_lagrangian_sph/ParallelThreshold.hpp"

#include <cmath>

namespace mfwave {

namespace {

// mirror[e] for every entry. The lists are symmetric (j in row i exactly when i in row j) and each
// row is sorted, so visiting the rows in increasing i meets the entries of row j in its order: the
// entry (i, j) mirrors the next unvisited entry of row j (one pass, no search). Checked on the way.
void findMirrors(const NeighbourList& list, Index count, std::vector<Index>& next,
                 std::vector<std::uint32_t>& mirror) {
  mirror.resize(list.indices.size());
  next.assign(static_cast<std::size_t>(count), 0);
  const Index* offsets = list.offsets.data();
  const Index* indices = list.indices.data();
  for (Index i = 0; i < count; ++i) {
    for (Index e = offsets[i]; e < offsets[i + 1]; ++e) {
      const Index j = indices[e];
      const Index position = next[static_cast<std::size_t>(j)]++;
      if (offsets[j] + position >= offsets[j + 1] || indices[offsets[j] + position] != i)
        throw Error("buildPairTable: the neighbour lists are not symmetric");
      mirror[static_cast<std::size_t>(e)] = static_cast<std::uint32_t>(position);
    }
  }
}

template <int D, class K>
void fillRows(const K& kernel, const NeighbourList& list, const Real* x, Index count,
              const PairTableSettings& settings, PairTable& table) {
  const Real support2 = kernel.supportRadius2();
  const Index* offsets = list.offsets.data();
  const Index* indices = list.indices.data();
  const std::uint32_t* mirror = table.mirror.data();
  std::uint8_t* inside = table.inside.data();
  Real* factor = table.gradientFactor.data();
  Real* smoothing = settings.xsph ? table.smoothingWeight.data() : nullptr;
  Real* stress = settings.artificialStress ? table.stressWeight.data() : nullptr;
  const Real* rho = settings.rho;
  // Row i evaluates its pairs with j > i and writes entry (i, j) and its mirror (j, i).
#pragma omp parallel for if (count > kParallelParticles) schedule(static)
  for (Index i = 0; i < count; ++i) {
    const Vec<D> xi = Eigen::Map<const Vec<D>>(x + i * D);
    for (Index e = offsets[i]; e < offsets[i + 1]; ++e) {
      const Index j = indices[e];
      if (j == i) inside[e] = 0;
      if (j <= i) continue;
      const Index m = offsets[j] + mirror[e];
      const Vec<D> r = xi - Eigen::Map<const Vec<D>>(x + j * D);
      const Real r2 = r.squaredNorm();
      if (r2 >= support2) {  // listed through the skin but outside the support
        inside[e] = inside[m] = 0;
        continue;
      }
      const Real distance = std::sqrt(r2);
      inside[e] = inside[m] = 1;
      factor[e] = factor[m] = kernel.gradientFactorAt(distance);
      if (smoothing != nullptr || stress != nullptr) {
        const Real w = kernel.valueAt(distance);
        if (smoothing != nullptr) smoothing[e] = smoothing[m] = 2 * w / (rho[i] + rho[j]);
        if (stress != nullptr)
          stress[e] = stress[m] =
              artificialStressWeight(w, settings.inverseReferenceKernel, settings.artificialStressExponent);
      }
    }
  }
}

}  // namespace

template <int D>
void buildPairTable(const Kernel& kernel, const NeighbourList& list, const Real* x, Index count,
                    const PairTableSettings& settings, PairTable& table) {
  const auto entries = list.indices.size();
  if (!table.mirrorValid || table.mirror.size() != entries) {
    findMirrors(list, count, table.mirrorScratch, table.mirror);
    table.mirrorValid = true;
  }
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
