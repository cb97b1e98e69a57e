#pragma once
// [[probe]]: a time series of one component of the displacement or velocity at one particle,
// chosen by index or as the particle nearest to a position.

#include "io/scene/GeometrySpec.hpp"
#include "io/scene/SceneReader.hpp"
#include "observers/ProbeRecorder.hpp"
#include "particles/ParticleSet.hpp"

#include <optional>
#include <string>
#include <vector>

namespace mfwave {

struct ProbeSpec {
  std::string name;
  std::optional<std::vector<Real>> position;  // exactly one of position and particle
  std::optional<Index> particle;
  ProbeQuantity quantity = ProbeQuantity::Velocity;
  int component = 0;  // 0 = x, 1 = y, 2 = z
};

std::vector<ProbeSpec> readProbes(SceneReader& reader, const GeometrySpec& geometry);

// The observers' probes: a position becomes the nearest physical particle of `particles`.
// Throws InputError("probe[i].particle") for an index beyond the physical particles.
template <int D>
std::vector<Probe> resolveProbes(const std::vector<ProbeSpec>& probes, const ParticleSet<D>& particles);

// The same on the box lattice of `geometry` without its particles: a position becomes the nearest
// lattice node (nearestLatticeNode, the node resolveProbes finds among makeLattice's particles,
// which come before any ghosts), so a rank of a split run places probes at no cost per node.
std::vector<Probe> resolveProbesOnLattice(const std::vector<ProbeSpec>& probes, const GeometrySpec& geometry);

}  // namespace mfwave
