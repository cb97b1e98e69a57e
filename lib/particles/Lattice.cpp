// Lattice generators: validation of box and spacing, and the node loop with face tagging.

#include "particles/Lattice.hpp"

#include "core/Error.hpp"
#include "particles/BoxFace.hpp"

#include <cmath>
#include <sstream>

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

template <int D>
ParticleSet<D> makeLattice(const Vec<D>& lower, const Vec<D>& upper, Real dx) {
  const std::array<Index, D> n = latticeIntervals<D>(lower, upper, dx);
  Index count = 1;
  for (int a = 0; a < D; ++a) count *= n[static_cast<std::size_t>(a)] + 1;

  ParticleSet<D> set;
  set.reserve(count);
  const Real nodeVolume = std::pow(dx, D);
  std::array<Index, D> node{};  // lattice index per axis, x fastest
  for (Index p = 0; p < count; ++p) {
    Vec<D> x;
    std::uint8_t faces = 0;
    for (int a = 0; a < D; ++a) {
      const Index i = node[static_cast<std::size_t>(a)];
      const Index last = n[static_cast<std::size_t>(a)];
      x[a] = i == last ? upper[a]
                       : lower[a] + (upper[a] - lower[a]) * static_cast<Real>(i) / static_cast<Real>(last);
      if (i == 0) faces |= faceBit(2 * a);
      if (i == last) faces |= faceBit(2 * a + 1);
    }
    set.add(x, nodeVolume, ParticleKind::Physical, faces, p);
    for (int a = 0; a < D; ++a) {  // advance the odometer
      auto& i = node[static_cast<std::size_t>(a)];
      if (++i <= n[static_cast<std::size_t>(a)]) break;
      i = 0;
    }
  }
  return set;
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

}  // namespace mfwave
