#pragma once
// The particles of a meshfree discretisation, stored as a structure of arrays.
//
// Why structure of arrays: the hot loops (neighbour search, kernel sums, force assembly) stream
// over one attribute of many particles at a time; separate contiguous arrays per coordinate and
// per attribute vectorise and cache well, and a method can keep its own per-particle fields in
// plain std::vectors alongside these without touching this class.
//
// Why global ids and kinds: a later domain decomposition splits the set across processes and
// appends halo copies; the stable globalId identifies a particle across processes and steps, and
// the kind separates particles that carry unknowns (Physical) from ghosts that only complete
// kernel supports near boundaries. Ghosts always come after the physical particles, so
// [0, physicalCount()) are the physical ones and loops over unknowns need no filtering.

#include "core/Types.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace mfwave {

// Named so that it does not clash with the scalar alias Real.
enum class ParticleKind : std::uint8_t { Physical, Ghost };

// One contiguous array per coordinate axis.
template <int D>
using Coordinates = std::array<std::vector<Real>, D>;

template <int D>
class ParticleSet {
  static_assert(D >= 1 && D <= 3, "ParticleSet supports 1, 2 and 3 dimensions");

 public:
  static constexpr int dimension = D;

  Index size() const { return static_cast<Index>(globalId.size()); }
  // Particles [0, physicalCount()) are Physical, the rest are Ghost.
  Index physicalCount() const { return physicalCount_; }
  Index ghostCount() const { return size() - physicalCount_; }
  // One more than the largest global id handed out so far: the next free id.
  Index nextGlobalId() const { return nextGlobalId_; }

  void reserve(Index count);

  // Appends a particle and returns its index. A negative id asks for nextGlobalId().
  // Throws Error when a Physical particle is appended after a ghost (the ordering invariant).
  Index add(const Vec<D>& x, Real particleVolume, ParticleKind particleKind = ParticleKind::Physical,
            std::uint8_t faces = 0, Index id = -1);

  Vec<D> position(Index i) const {
    Vec<D> x;
    for (int a = 0; a < D; ++a) x[a] = coords_[a][static_cast<std::size_t>(i)];
    return x;
  }
  void setPosition(Index i, const Vec<D>& x) {
    for (int a = 0; a < D; ++a) coords_[a][static_cast<std::size_t>(i)] = x[a];
  }
  const std::vector<Real>& coordinate(int axis) const { return coords_[static_cast<std::size_t>(axis)]; }
  // Mutable access for bulk moves (a time step updating all positions at once).
  std::vector<Real>& coordinate(int axis) { return coords_[static_cast<std::size_t>(axis)]; }
  const Coordinates<D>& coordinates() const { return coords_; }

  // Number of box faces particle i lies on: 0 interior, 1 face, 2 edge, 3 corner (in 3-D).
  int facetCount(Index i) const;
  // Normalised sum of the unit outward normals of the faces particle i lies on; zero inside.
  // At an edge or corner this is the bisecting direction, e.g. (-1,-1,-1)/sqrt(3).
  Vec<D> outwardNormal(Index i) const;
  // The unit outward normal of each face particle i lies on, in face order (empty inside).
  // Boundary conditions at edges and corners are imposed per facet with these.
  std::vector<Vec<D>> facetNormals(Index i) const;

  // Per-particle attributes, all of length size().
  std::vector<Index> globalId;
  std::vector<ParticleKind> kind;
  // Nominal volume (dx^D on a lattice, also for boundary particles and ghosts).
  std::vector<Real> volume;
  // Bit BoxFace k set when the particle lies on box face k (see BoxFace.hpp); 0 for ghosts.
  std::vector<std::uint8_t> faceMask;

 private:
  Coordinates<D> coords_;
  Index physicalCount_ = 0;
  Index nextGlobalId_ = 0;
};

extern template class ParticleSet<1>;
extern template class ParticleSet<2>;
extern template class ParticleSet<3>;

}  // namespace mfwave
