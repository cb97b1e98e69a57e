#include "wiring/LambReference.hpp"

#include "particles/BoxFace.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdlib>

namespace mfwave {

std::string lambReferenceUnavailable(const Scene& scene) {
  if (scene.loads.size() != 1 || scene.loads[0].type != LoadType::SurfacePatch)
    return "the exact reference needs exactly one surface_patch load";
  const int d = scene.info.dimension;
  if (d != 2 && d != 3) return "the exact reference is for 2-D and 3-D scenes";
  const LoadSpec& load = scene.loads[0];
  const auto axis = static_cast<std::size_t>(load.face / 2);
  std::vector<Real> widths;
  for (std::size_t a = 0; a < static_cast<std::size_t>(d); ++a)
    if (a != axis) widths.push_back(load.halfWidth[a]);
  if (d == 3 && std::abs(widths[0] - widths[1]) > 1e-12 * widths[0]) return "the exact reference needs a square patch";
  for (std::size_t a = 0; a < static_cast<std::size_t>(d); ++a)
    if (a != axis && load.traction[a] != 0) return "the exact reference needs a normal traction";
  const Material material = scene.material.material();
  if (d == 3 && std::abs(material.lambda() - material.mu()) > 1e-12 * material.mu())
    return "the exact 3-D reference (Pekeris) needs a Poisson solid, lambda = mu";
  if (d == 2 && material.lambda() < 0) return "the exact 2-D reference needs lambda >= 0";
  std::vector<Real> times, values;
  if (!load.timeFunction.piecewiseLinear(times, values) || values.front() != 0)
    return "the exact reference needs a piecewise-linear load history starting from 0";
  return "";
}

namespace {

// What every exact solution reads of a Lamb scene's one surface patch: the material, the load
// history's breakpoints, the half-width along the face and the normal traction p (the solutions
// give the response along the applied traction, i.e. the normal component for traction p n_axis,
// p of either sign, by linearity).
struct LambLoad {
  Material material;
  std::vector<Real> times, values;
  Real halfWidth = 0, pressure = 0;
};

LambLoad lambLoad(const Scene& scene) {
  const LoadSpec& load = scene.loads[0];
  LambLoad read{scene.material.material(), {}, {}, 0, 0};
  load.timeFunction.piecewiseLinear(read.times, read.values);
  const auto d = static_cast<std::size_t>(scene.info.dimension);
  const auto axis = static_cast<std::size_t>(load.face / 2);
  read.halfWidth = load.halfWidth[(axis + 1) % d];
  read.pressure = load.traction[axis];
  return read;
}

}  // namespace

LambSquareLoad lambReference(const Scene& scene) {
  LambLoad load = lambLoad(scene);
  return LambSquareLoad(load.material.mu(), load.material.sWaveSpeed(), load.halfWidth, std::move(load.times),
                        std::move(load.values), load.pressure);
}

template <int D>
ProbeSite<D> probeSite(const ParticleSet<D>& particles, Index particle) {
  return {particles.position(particle), particles.faceMask[static_cast<std::size_t>(particle)]};
}

template <int D>
std::optional<LambReceiver> lambReceiver(const Scene& scene, const ParticleSet<D>& particles, const Probe& probe) {
  return lambReceiver<D>(scene, probeSite<D>(particles, probe.particle), probe);
}

template <int D>
std::optional<LambReceiver> lambReceiver(const Scene& scene, const ProbeSite<D>& site, const Probe& probe) {
  if (scene.loads.empty()) return std::nullopt;
  const LoadSpec& load = scene.loads[0];
  const int axis = load.face / 2;
  if (probe.component != axis) return std::nullopt;
  const Vec<D>& x = site.position;
  LambReceiver receiver;
  for (int k = 0; k + 1 < D; ++k) {
    const auto a = static_cast<std::size_t>((axis + 1 + k) % D);
    receiver.offset[static_cast<std::size_t>(k)] = x[static_cast<Index>(a)] - load.centre[a];
  }
  const bool onFace = (site.faceMask & faceBit(load.face)) != 0;
  if (onFace) return receiver;
  receiver.depth = std::abs(x[axis] - load.centre[static_cast<std::size_t>(axis)]);
  if (D == 2) return receiver;
  // 3-D inside: on the load's axis only (to rounding of the lattice positions).
  const Real scale = std::max<Real>(load.halfWidth[static_cast<std::size_t>((axis + 1) % D)], 1);
  if (std::abs(receiver.offset[0]) > 1e-9 * scale || std::abs(receiver.offset[1]) > 1e-9 * scale)
    return std::nullopt;
  receiver.offset = {0, 0};
  return receiver;
}

template ProbeSite<2> probeSite<2>(const ParticleSet<2>&, Index);
template ProbeSite<3> probeSite<3>(const ParticleSet<3>&, Index);
template std::optional<LambReceiver> lambReceiver<2>(const Scene&, const ParticleSet<2>&, const Probe&);
template std::optional<LambReceiver> lambReceiver<3>(const Scene&, const ParticleSet<3>&, const Probe&);
template std::optional<LambReceiver> lambReceiver<2>(const Scene&, const ProbeSite<2>&, const Probe&);
template std::optional<LambReceiver> lambReceiver<3>(const Scene&, const ProbeSite<3>&, const Probe&);

LambExactResponse::LambExactResponse(const Scene& scene) {
  LambLoad load = lambLoad(scene);
  const Material& m = load.material;
  if (scene.info.dimension == 2) {
    strip_.emplace(m.lambda(), m.mu(), m.density(), load.halfWidth, std::move(load.times), std::move(load.values),
                   load.pressure);
    return;
  }
  buried_.emplace(m.lambda(), m.mu(), m.density(), SurfaceLoadShape::Square, load.halfWidth, load.times, load.values,
                  load.pressure);
  square_.emplace(lambReference(scene));
}

// The buried 3-D receiver by f-k integration on a 1/64 grid up to the horizon (once per depth and
// span: the probes' scoring and the fine exact.csv grid ask for the same one), interpolated to `times`.
std::vector<Real> LambExactResponse::buriedSeries(Real depth, const std::vector<Real>& times, bool velocity,
                                                  Real horizon) const {
  Real end = 0;
  for (const Real t : times)
    if (t <= horizon) end = std::max(end, t);
  std::vector<Real> series(times.size(), std::numeric_limits<Real>::quiet_NaN());
  for (std::size_t i = 0; i < times.size(); ++i)
    if (times[i] <= 0) series[i] = 0;
  if (!(end > 0)) return series;
  const Real steps = std::ceil(64 * end), dt = end / steps;
  auto found = buriedCache_.find({depth, end});
  if (found == buriedCache_.end())
    found = buriedCache_.emplace(std::make_pair(depth, end), buried_->response(0, depth, end, dt)).first;
  const HalfSpaceFrequencyWavenumber::Series& fine = found->second;
  const std::vector<Real>& samples = velocity ? fine.velocity : fine.displacement;
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (!(times[i] > 0 && times[i] <= end)) continue;
    const Real position = std::clamp<Real>(times[i] / dt, 0, static_cast<Real>(samples.size() - 1));
    const auto k = std::min(static_cast<std::size_t>(position), samples.size() - 2);
    const Real w = position - static_cast<Real>(k);
    series[i] = (1 - w) * samples[k] + w * samples[k + 1];
  }
  return series;
}

std::vector<Real> LambExactResponse::series(const LambReceiver& receiver, const std::vector<Real>& times,
                                            bool velocity, Real horizon) const {
  if (square_ && receiver.depth > 0) return buriedSeries(receiver.depth, times, velocity, horizon);
  std::vector<Real> series;
  series.reserve(times.size());
  const auto& o = receiver.offset;
  for (const Real t : times) {
    if (strip_)
      series.push_back(velocity ? strip_->velocity(o[0], receiver.depth, t)
                                : strip_->displacement(o[0], receiver.depth, t));
    else
      series.push_back(velocity ? square_->velocity(o[0], o[1], t) : square_->displacement(o[0], o[1], t));
  }
  return series;
}

std::vector<Real> kernelSmoothedLambSeries(const LambSquareLoad& exact, const Kernel& kernel,
                                           const std::array<Real, 2>& offset, const std::vector<Real>& times,
                                           bool velocity) {
  const Real radius = kernel.supportRadius();
  constexpr int inPlane = 12, normal = 40;
  std::vector<std::array<Real, 3>> shifts;
  Real total = 0;
  for (int i = -inPlane; i <= inPlane; ++i)
    for (int j = -inPlane; j <= inPlane; ++j) {
      const Real zx = radius * i / inPlane, zy = radius * j / inPlane;
      Real density = 0;
      for (int k = -normal; k <= normal; ++k) density += kernel.value(Vec3(zx, zy, radius * k / normal));
      if (density > 0) {
        shifts.push_back({zx, zy, density});
        total += density;
      }
    }
  std::vector<Real> smoothed;
  smoothed.reserve(times.size());
  for (const Real t : times) {
    Real sum = 0;
    for (const auto& [zx, zy, weight] : shifts) {
      const Real px = offset[0] - zx, py = offset[1] - zy;
      sum += weight * (velocity ? exact.velocity(px, py, t) : exact.displacement(px, py, t));
    }
    smoothed.push_back(sum / total);
  }
  return smoothed;
}

}  // namespace mfwave
