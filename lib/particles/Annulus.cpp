#include "particles/Annulus.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace mfwave {
namespace {

constexpr Real pi = kPi;

}  // namespace

ParticleSet<2> makeAnnulus(const Vec2& centre, Real innerRadius, Real outerRadius, Real spacing) {
  if (!centre.allFinite()) throw InputError("centre", "must be finite");
  if (!(innerRadius >= 0) || !std::isfinite(innerRadius))
    throw InputError("inner_radius", "must be >= 0 and finite, got " + std::to_string(innerRadius));
  if (!(outerRadius > innerRadius) || !std::isfinite(outerRadius))
    throw InputError("outer_radius", "must be finite and above inner_radius = " + std::to_string(innerRadius) +
                                         ", got " + std::to_string(outerRadius));
  if (!(spacing > 0) || !std::isfinite(spacing))
    throw InputError("spacing", "must be positive and finite, got " + std::to_string(spacing));

  const Real width = outerRadius - innerRadius;
  const Index rings = std::max<Index>(1, std::llround(width / spacing));
  const Real dr = width / static_cast<Real>(rings);
  ParticleSet<2> set;
  for (Index k = 0; k < rings; ++k) {
    const Real r = innerRadius + (static_cast<Real>(k) + 0.5) * dr;
    const Index count = std::max<Index>(1, std::llround(2 * pi * r / spacing));
    const Real volume = 2 * pi * r * dr / static_cast<Real>(count);
    const Real turn = (k % 2 == 1) ? 0.5 : 0.0;
    for (Index j = 0; j < count; ++j) {
      const Real angle = 2 * pi * (static_cast<Real>(j) + turn) / static_cast<Real>(count);
      set.add(Vec2(centre.x() + r * std::cos(angle), centre.y() + r * std::sin(angle)), volume);
    }
  }
  return set;
}

template <int D>
void appendParticles(ParticleSet<D>& into, const ParticleSet<D>& from) {
  into.reserve(into.size() + from.size());
  for (Index i = 0; i < from.size(); ++i) {
    const auto s = static_cast<std::size_t>(i);
    into.add(from.position(i), from.volume[s], from.kind[s], from.faceMask[s]);
  }
}

template void appendParticles<1>(ParticleSet<1>&, const ParticleSet<1>&);
template void appendParticles<2>(ParticleSet<2>&, const ParticleSet<2>&);
template void appendParticles<3>(ParticleSet<3>&, const ParticleSet<3>&);

}  // namespace mfwave
