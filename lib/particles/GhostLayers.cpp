// Ghost layers: walk the lattice extended by `layers` on the chosen sides and keep the points
// that lie outside the box.

#include "particles/GhostLayers.hpp"

#include "core/Error.hpp"
#include "particles/BoxFace.hpp"
#include "particles/Lattice.hpp"

#include <array>
#include <cmath>
#include <string>

namespace mfwave {

namespace {

// The checks, then the extended index range per axis ([first, last], with extra layers only on
// chosen sides) and the ghost count.
template <int D>
Index extendedRange(const Vec<D>& lower, const Vec<D>& upper, Real dx, int layers, std::uint8_t faces,
                    std::array<Index, D>& n, std::array<Index, D>& first, std::array<Index, D>& last) {
  if (layers < 0) {
    throw InputError("ghost_layers", "must be zero or more, got " + std::to_string(layers));
  }
  if ((faces & ~allFaces(D)) != 0) {
    throw InputError("ghost_faces", "mask " + std::to_string(faces) + " names faces that a " +
                                        std::to_string(D) + "-D box does not have");
  }
  n = latticeIntervals<D>(lower, upper, dx);
  Index extendedCount = 1;
  Index boxCount = 1;
  for (int a = 0; a < D; ++a) {
    const auto s = static_cast<std::size_t>(a);
    first[s] = (faces & faceBit(2 * a)) ? -layers : 0;
    last[s] = n[s] + ((faces & faceBit(2 * a + 1)) ? layers : 0);
    extendedCount *= last[s] - first[s] + 1;
    boxCount *= n[s] + 1;
  }
  return extendedCount - boxCount;
}

}  // namespace

template <int D>
Index ghostLayerCount(const Vec<D>& lower, const Vec<D>& upper, Real dx, int layers, std::uint8_t faces) {
  std::array<Index, D> n{}, first{}, last{};
  return extendedRange<D>(lower, upper, dx, layers, faces, n, first, last);
}

template <int D>
Index addGhostLayers(ParticleSet<D>& set, const Vec<D>& lower, const Vec<D>& upper, Real dx,
                     int layers, std::uint8_t faces) {
  std::array<Index, D> n{}, first{}, last{};
  const Index ghosts = extendedRange<D>(lower, upper, dx, layers, faces, n, first, last);
  Index extendedCount = 1;
  for (std::size_t s = 0; s < static_cast<std::size_t>(D); ++s) extendedCount *= last[s] - first[s] + 1;
  if (ghosts == 0) return 0;

  set.reserve(set.size() + ghosts);
  const Real nodeVolume = std::pow(dx, D);
  std::array<Index, D> node = first;
  for (Index p = 0; p < extendedCount; ++p) {
    bool outside = false;
    Vec<D> x;
    for (int a = 0; a < D; ++a) {
      const auto s = static_cast<std::size_t>(a);
      const Index i = node[s];
      outside = outside || i < 0 || i > n[s];
      x[a] = lower[a] + (upper[a] - lower[a]) * static_cast<Real>(i) / static_cast<Real>(n[s]);
    }
    if (outside) set.add(x, nodeVolume, ParticleKind::Ghost, 0);
    for (int a = 0; a < D; ++a) {  // advance the odometer over the extended range
      const auto s = static_cast<std::size_t>(a);
      if (++node[s] <= last[s]) break;
      node[s] = first[s];
    }
  }
  return ghosts;
}

template Index ghostLayerCount<1>(const Vec1&, const Vec1&, Real, int, std::uint8_t);
template Index ghostLayerCount<2>(const Vec2&, const Vec2&, Real, int, std::uint8_t);
template Index ghostLayerCount<3>(const Vec3&, const Vec3&, Real, int, std::uint8_t);
template Index addGhostLayers<1>(ParticleSet<1>&, const Vec1&, const Vec1&, Real, int, std::uint8_t);
template Index addGhostLayers<2>(ParticleSet<2>&, const Vec2&, const Vec2&, Real, int, std::uint8_t);
template Index addGhostLayers<3>(ParticleSet<3>&, const Vec3&, const Vec3&, Real, int, std::uint8_t);

}  // namespace mfwave
