#include "io/scene/ProbeSpec.hpp"

#include "io/scene/Faces.hpp"
#include "io/scene/Format.hpp"
#include "io/scene/ScenePath.hpp"
#include "particles/Lattice.hpp"

#include <limits>

namespace mfwave {

std::vector<ProbeSpec> readProbes(SceneReader& reader, const GeometrySpec& geometry) {
  const auto d = static_cast<std::size_t>(geometry.dimension);
  std::vector<ProbeSpec> probes;
  const std::size_t count = reader.count("probe");
  for (std::size_t i = 0; i < count; ++i) {
    const std::string entry = scene::indexPath("probe", i);
    const auto key = [&](const char* name) { return scene::childPath(entry, name); };
    ProbeSpec p;
    p.name = reader.string(key("name"));
    if (p.name.empty()) reader.fail(key("name"), "must not be empty");
    for (std::size_t j = 0; j < probes.size(); ++j)
      if (probes[j].name == p.name)
        reader.fail(key("name"), "'" + p.name + "' is already the name of probe[" + std::to_string(j) +
                                     "]; probe names must be unique");
    const bool position = reader.has(key("position")), particle = reader.has(key("particle"));
    if (position && particle)
      reader.fail(key("particle"), "cannot be combined with position: give exactly one of position and particle");
    if (!position && !particle)
      reader.fail(key("position"), "missing required key (give position, or particle)");
    if (position) {
      p.position = reader.numbers(key("position"), d);
      if (!geometry.contains(*p.position))
        reader.fail(key("position"), scene::formatPoint(*p.position) + " lies outside the geometry box " +
                                         geometry.describeBox());
    } else {
      p.particle = static_cast<Index>(reader.integer(key("particle")));
      if (*p.particle >= geometry.particleCount())
        reader.fail(key("particle"), "must be less than the number of particles, " +
                                         std::to_string(geometry.particleCount()) + ", got " +
                                         std::to_string(*p.particle));
    }
    p.quantity = reader.string(key("quantity")) == "displacement" ? ProbeQuantity::Displacement : ProbeQuantity::Velocity;
    p.component = readComponent(reader, key("component"), geometry.dimension);
    probes.push_back(std::move(p));
  }
  return probes;
}

namespace {

// The probes with each position placed by `nearest` and each particle index checked against `count`.
template <class Nearest>
std::vector<Probe> resolveWith(const std::vector<ProbeSpec>& probes, Index count, Nearest&& nearest) {
  std::vector<Probe> out;
  for (std::size_t i = 0; i < probes.size(); ++i) {
    const ProbeSpec& spec = probes[i];
    Probe probe;
    probe.name = spec.name;
    probe.component = spec.component;
    probe.quantity = spec.quantity;
    if (spec.particle) {
      if (*spec.particle >= count)
        throw InputError(scene::childPath(scene::indexPath("probe", i), "particle"),
                         "must be less than the number of particles, " + std::to_string(count));
      probe.particle = *spec.particle;
    } else {
      probe.particle = nearest(*spec.position);
    }
    out.push_back(probe);
  }
  return out;
}

template <int D>
std::vector<Probe> resolveOnLattice(const std::vector<ProbeSpec>& probes, const GeometrySpec& geometry) {
  const Vec<D> lower = Eigen::Map<const Vec<D>>(geometry.lower.data());
  const Vec<D> upper = Eigen::Map<const Vec<D>>(geometry.upper.data());
  return resolveWith(probes, static_cast<Index>(geometry.particleCount()), [&](const std::vector<Real>& position) {
    return nearestLatticeNode<D>(lower, upper, geometry.spacing, Eigen::Map<const Vec<D>>(position.data()));
  });
}

}  // namespace

template <int D>
std::vector<Probe> resolveProbes(const std::vector<ProbeSpec>& probes, const ParticleSet<D>& particles) {
  return resolveWith(probes, particles.physicalCount(), [&](const std::vector<Real>& position) {
    const Vec<D> x = Eigen::Map<const Vec<D>>(position.data());
    Index nearest = 0;
    Real best = std::numeric_limits<Real>::infinity();
    for (Index p = 0; p < particles.physicalCount(); ++p) {
      const Real distance = (particles.position(p) - x).squaredNorm();
      if (distance < best) {
        best = distance;
        nearest = p;
      }
    }
    return nearest;
  });
}

std::vector<Probe> resolveProbesOnLattice(const std::vector<ProbeSpec>& probes, const GeometrySpec& geometry) {
  switch (geometry.dimension) {
    case 1:
      return resolveOnLattice<1>(probes, geometry);
    case 2:
      return resolveOnLattice<2>(probes, geometry);
    default:
      return resolveOnLattice<3>(probes, geometry);
  }
}

template std::vector<Probe> resolveProbes<1>(const std::vector<ProbeSpec>&, const ParticleSet<1>&);
template std::vector<Probe> resolveProbes<2>(const std::vector<ProbeSpec>&, const ParticleSet<2>&);
template std::vector<Probe> resolveProbes<3>(const std::vector<ProbeSpec>&, const ParticleSet<3>&);

}  // namespace mfwave
