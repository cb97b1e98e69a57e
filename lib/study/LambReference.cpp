#include "study/LambReference.hpp"

#include "particles/BoxFace.hpp"

#include <cmath>
#include <cstdlib>

namespace mfwave {

std::string lambReferenceUnavailable(const Scene& scene) {
  if (scene.loads.size() != 1 || scene.loads[0].type != LoadType::SurfacePatch)
    return "the exact reference needs exactly one surface_patch load";
  const LoadSpec& load = scene.loads[0];
  const auto axis = static_cast<std::size_t>(load.face / 2);
  std::vector<Real> widths;
  for (std::size_t a = 0; a < 3; ++a)
    if (a != axis) widths.push_back(load.halfWidth[a]);
  if (std::abs(widths[0] - widths[1]) > 1e-12 * widths[0]) return "the exact reference needs a square patch";
  for (std::size_t a = 0; a < 3; ++a)
    if (a != axis && load.traction[a] != 0) return "the exact reference needs a normal traction";
  const Material material = scene.material.material();
  if (std::abs(material.lambda() - material.mu()) > 1e-12 * material.mu())
    return "the exact reference (Pekeris) needs a Poisson solid, lambda = mu";
  std::vector<Real> times, values;
  if (!load.timeFunction.piecewiseLinear(times, values) || values.front() != 0)
    return "the exact reference needs a piecewise-linear load history starting from 0";
  return "";
}

LambSquareLoad lambReference(const Scene& scene) {
  const LoadSpec& load = scene.loads[0];
  const Material material = scene.material.material();
  std::vector<Real> times, values;
  load.timeFunction.piecewiseLinear(times, values);
  const auto axis = static_cast<std::size_t>(load.face / 2);
  const Real halfWidth = load.halfWidth[(axis + 1) % 3];
  // LambSquareLoad gives the response along the applied traction, i.e. the normal component for
  // traction p n_axis (p of either sign, by linearity).
  return LambSquareLoad(material.mu(), material.sWaveSpeed(), halfWidth, std::move(times), std::move(values),
                        load.traction[axis]);
}

std::optional<std::array<Real, 2>> lambSurfaceOffset(const Scene& scene, const ParticleSet<3>& particles,
                                                     const Probe& probe) {
  if (scene.loads.empty()) return std::nullopt;
  const LoadSpec& load = scene.loads[0];
  const int axis = load.face / 2;
  const bool onFace = (particles.faceMask[static_cast<std::size_t>(probe.particle)] & faceBit(load.face)) != 0;
  if (!onFace || probe.component != axis) return std::nullopt;
  const Vec3 x = particles.position(probe.particle);
  const auto first = static_cast<std::size_t>((axis + 1) % 3), second = static_cast<std::size_t>((axis + 2) % 3);
  return std::array<Real, 2>{x[static_cast<Index>(first)] - load.centre[first],
                             x[static_cast<Index>(second)] - load.centre[second]};
}

std::vector<Real> lambExactSeries(const LambSquareLoad& exact, const std::array<Real, 2>& offset,
                                  const std::vector<Real>& times, bool velocity) {
  std::vector<Real> series;
  series.reserve(times.size());
  for (const Real t : times)
    series.push_back(velocity ? exact.velocity(offset[0], offset[1], t) : exact.displacement(offset[0], offset[1], t));
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
