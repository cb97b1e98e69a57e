// Lattice generators: validation of box and spacing, and the node loop with face tagging.

#include "particles/Lattice.hpp"

#include "core/Error.hpp"
#include "particles/BoxFace.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace mfwave {

namespace {

// Guard against a spacing so small that the lattice could not be allocated anyway.
constexpr Real kMaxParticles = 1e10;

std::string str(Real value) {
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

}  // namespace

template <int D>
std::array<Index, D> latticeIntervals(const Vec<D>& lower, const Vec<D>& upper, Real dx) {
  if (!std::isfinite(dx) || dx <= 0) {
    throw InputError("spacing", "must be positive and finite, got " + str(dx));
  }
  std::array<Index, D> intervals{};
  Real total = 1;
  for (int a = 0; a < D; ++a) {
    if (!std::isfinite(lower[a]) || !std::isfinite(upper[a])) {
      throw InputError("geometry", std::string("box bounds must be finite along axis ") + axisName(a));
    }
    if (!(upper[a] > lower[a])) {
      throw InputError("geometry", "upper bound " + str(upper[a]) + " is not above lower bound " +
                                       str(lower[a]) + " along axis " + axisName(a));
    }
    const Real length = upper[a] - lower[a];
    const Real ratio = length / dx;
    const Real rounded = std::round(ratio);
    if (rounded < 1 || std::abs(ratio - rounded) > 1e-9 * ratio) {
      throw InputError("spacing", str(dx) + " does not divide the length " + str(length) +
                                      " along axis " + axisName(a));
    }
    total *= rounded + 1;
    if (total > kMaxParticles) {
      throw InputError("spacing", str(dx) + " would create more than 1e10 particles");
    }
    intervals[static_cast<std::size_t>(a)] = static_cast<Index>(rounded);
  }
  return intervals;
}

namespace {

// Node i of n intervals along axis a: lower + (upper - lower) i / n, the far end exactly.
template <int D>
Real nodeCoordinate(const Vec<D>& lower, const Vec<D>& upper, Index last, int a, Index i) {
  return i == last ? upper[a] : lower[a] + (upper[a] - lower[a]) * static_cast<Real>(i) / static_cast<Real>(last);
}

}  // namespace

template <int D>
ParticleSet<D> makeLattice(const Vec<D>& lower, const Vec<D>& upper, Real dx) {
  const std::array<Index, D> n = latticeIntervals<D>(lower, upper, dx);
  std::array<Index, D> first{}, end{};
  for (int a = 0; a < D; ++a) end[static_cast<std::size_t>(a)] = n[static_cast<std::size_t>(a)] + 1;
  return makeLattice<D>(lower, upper, dx, first, end);
}

template <int D>
ParticleSet<D> makeLattice(const Vec<D>& lower, const Vec<D>& upper, Real dx, const std::array<Index, D>& first,
                           const std::array<Index, D>& end) {
  const std::array<Index, D> n = latticeIntervals<D>(lower, upper, dx);
  Index count = 1;
  for (int a = 0; a < D; ++a) {
    const auto s = static_cast<std::size_t>(a);
    if (first[s] < 0 || end[s] > n[s] + 1 || end[s] <= first[s])
      throw InputError("lattice", "the nodes [" + std::to_string(first[s]) + ", " + std::to_string(end[s]) +
                                      ") along axis " + std::to_string(a) + " are not a block of its " +
                                      std::to_string(n[s] + 1) + " nodes");
    count *= end[s] - first[s];
  }

  ParticleSet<D> set;
  set.reserve(count);
  const Real nodeVolume = std::pow(dx, D);
  std::array<Index, D> node = first;  // lattice index per axis, x fastest
  for (Index p = 0; p < count; ++p) {
    Vec<D> x;
    Index id = 0;
    for (int a = D - 1; a >= 0; --a) {
      const auto s = static_cast<std::size_t>(a);
      const Index i = node[s];
      x[a] = nodeCoordinate<D>(lower, upper, n[s], a, i);
      id = id * (n[s] + 1) + i;
    }
    set.add(x, nodeVolume, ParticleKind::Physical, latticeFaceMask<D>(n, node), id);
    for (int a = 0; a < D; ++a) {  // advance the odometer
      auto& i = node[static_cast<std::size_t>(a)];
      if (++i < end[static_cast<std::size_t>(a)]) break;
      i = first[static_cast<std::size_t>(a)];
    }
  }
  return set;
}

template <int D>
Index nearestLatticeNode(const Vec<D>& lower, const Vec<D>& upper, Real dx, const Vec<D>& x) {
  const std::array<Index, D> n = latticeIntervals<D>(lower, upper, dx);
  Index node = 0;
  for (int a = D - 1; a >= 0; --a) {
    const Index last = n[static_cast<std::size_t>(a)];
    // The candidates around the rounded-down position, the nearest by the nodes' own coordinates,
    // the lower one on a tie (as a search over the particles in their order would pick).
    const Real t = (x[a] - lower[a]) / (upper[a] - lower[a]) * static_cast<Real>(last);
    const Index guess = std::isfinite(t) ? static_cast<Index>(std::floor(std::clamp(t, Real(-1), static_cast<Real>(last) + 1))) : 0;
    Index best = -1;
    Real bestDistance = std::numeric_limits<Real>::infinity();
    for (Index i = std::max<Index>(guess - 1, 0); i <= std::min<Index>(guess + 2, last); ++i) {
      const Real d = nodeCoordinate<D>(lower, upper, last, a, i) - x[a];
      if (d * d < bestDistance) {
        bestDistance = d * d;
        best = i;
      }
    }
    if (best < 0) best = guess < 0 ? 0 : last;
    node = node * (last + 1) + best;
  }
  return node;
}

ParticleSet<1> makeLine(Real x0, Real x1, Real dx) {
  return makeLattice<1>(Vec1::Constant(x0), Vec1::Constant(x1), dx);
}
ParticleSet<2> makeRectangle(const Vec2& lower, const Vec2& upper, Real dx) {
  return makeLattice<2>(lower, upper, dx);
}
ParticleSet<3> makeBlock(const Vec3& lower, const Vec3& upper, Real dx) {
  return makeLattice<3>(lower, upper, dx);
}

template std::array<Index, 1> latticeIntervals<1>(const Vec1&, const Vec1&, Real);
template std::array<Index, 2> latticeIntervals<2>(const Vec2&, const Vec2&, Real);
template std::array<Index, 3> latticeIntervals<3>(const Vec3&, const Vec3&, Real);
template ParticleSet<1> makeLattice<1>(const Vec1&, const Vec1&, Real);
template ParticleSet<2> makeLattice<2>(const Vec2&, const Vec2&, Real);
template ParticleSet<3> makeLattice<3>(const Vec3&, const Vec3&, Real);
template ParticleSet<1> makeLattice<1>(const Vec1&, const Vec1&, Real, const std::array<Index, 1>&, const std::array<Index, 1>&);
template ParticleSet<2> makeLattice<2>(const Vec2&, const Vec2&, Real, const std::array<Index, 2>&, const std::array<Index, 2>&);
template ParticleSet<3> makeLattice<3>(const Vec3&, const Vec3&, Real, const std::array<Index, 3>&, const std::array<Index, 3>&);
template Index nearestLatticeNode<1>(const Vec1&, const Vec1&, Real, const Vec1&);
template Index nearestLatticeNode<2>(const Vec2&, const Vec2&, Real, const Vec2&);
template Index nearestLatticeNode<3>(const Vec3&, const Vec3&, Real, const Vec3&);

}  // namespace mfwave
