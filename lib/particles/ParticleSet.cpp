// ParticleSet: appending particles and the geometry of boundary facets.

#include "particles/ParticleSet.hpp"

#include "core/Error.hpp"
#include "particles/BoxFace.hpp"

#include <algorithm>

namespace mfwave {

template <int D>
void ParticleSet<D>::reserve(Index count) {
  const auto n = static_cast<std::size_t>(count);
  for (auto& c : coords_) c.reserve(n);
  globalId.reserve(n);
  kind.reserve(n);
  volume.reserve(n);
  faceMask.reserve(n);
}

template <int D>
Index ParticleSet<D>::add(const Vec<D>& x, Real particleVolume, ParticleKind particleKind,
                          std::uint8_t faces, Index id) {
  if (particleKind == ParticleKind::Physical && physicalCount_ != size()) {
    throw Error("ParticleSet::add: a physical particle cannot follow ghost particles");
  }
  const Index i = size();
  for (int a = 0; a < D; ++a) coords_[static_cast<std::size_t>(a)].push_back(x[a]);
  const Index assigned = id < 0 ? nextGlobalId_ : id;
  globalId.push_back(assigned);
  nextGlobalId_ = std::max(nextGlobalId_, assigned + 1);
  kind.push_back(particleKind);
  volume.push_back(particleVolume);
  faceMask.push_back(static_cast<std::uint8_t>(faces & allFaces(D)));
  if (particleKind == ParticleKind::Physical) ++physicalCount_;
  return i;
}

template <int D>
int ParticleSet<D>::facetCount(Index i) const {
  const unsigned mask = faceMask[static_cast<std::size_t>(i)];
  int count = 0;
  for (int face = 0; face < 2 * D; ++face) count += (mask >> face) & 1u;
  return count;
}

template <int D>
Vec<D> ParticleSet<D>::outwardNormal(Index i) const {
  Vec<D> sum = Vec<D>::Zero();
  for (const Vec<D>& n : facetNormals(i)) sum += n;
  const Real length = sum.norm();
  return length > 0 ? Vec<D>(sum / length) : sum;
}

template <int D>
std::vector<Vec<D>> ParticleSet<D>::facetNormals(Index i) const {
  const unsigned mask = faceMask[static_cast<std::size_t>(i)];
  std::vector<Vec<D>> normals;
  for (int face = 0; face < 2 * D; ++face) {
    if ((mask >> face) & 1u) normals.push_back(faceNormal<D>(face));
  }
  return normals;
}

template class ParticleSet<1>;
template class ParticleSet<2>;
template class ParticleSet<3>;

}  // namespace mfwave
