#pragma once
// The exact reference of a Lamb scene: a half-space loaded on its free surface by one patch of
// normal traction with a piecewise-linear history from 0, in 2-D (a strip: LambStripLoad,
// Cagniard-de Hoop, any Poisson ratio, any receiver) or in 3-D (a square on a Poisson solid,
// lambda = mu: LambSquareLoad on the surface, Ding et al. section 8, and a frequency-wavenumber
// integration, HalfSpaceFrequencyWavenumber, below the load centre), and where a probe sees it.
// Nothing here depends on the method: every method that runs a Lamb scene scores its probes
// through these functions.

#include "analytic/HalfSpaceFrequencyWavenumber.hpp"
#include "analytic/LambSquareLoad.hpp"
#include "analytic/LambStripLoad.hpp"
#include "io/scene/Scene.hpp"
#include "kernels/Kernel.hpp"
#include "observers/ProbeRecorder.hpp"
#include "particles/ParticleSet.hpp"

#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace mfwave {

// Why the scene has no exact reference ("" when it has one).
std::string lambReferenceUnavailable(const Scene& scene);

// The 3-D surface solution for the scene's load (a 3-D scene with a reference).
LambSquareLoad lambReference(const Scene& scene);

// A receiver the exact reference serves, for a probe reading the component normal to the loaded
// face: offset = its position relative to the load centre along the face (in 3-D the two in-plane
// axes in cyclic order after the normal; in 2-D the other axis, offset[1] = 0), depth = its
// distance below the face (0 on the face).
struct LambReceiver {
  std::array<Real, 2> offset{0, 0};
  Real depth = 0;
};

// Where the reference applies to `probe`: the normal component anywhere on the loaded face, and
// inside the body anywhere in 2-D but in 3-D only on the load's axis (where the f-k reference is
// computed); nothing otherwise.
template <int D>
std::optional<LambReceiver> lambReceiver(const Scene& scene, const ParticleSet<D>& particles, const Probe& probe);

// Where a probe reads: its particle's position and face tags (from the particle set, or from the
// lattice alone on a rank that does not hold the probe's particle).
template <int D>
struct ProbeSite {
  Vec<D> position = Vec<D>::Zero();
  std::uint8_t faceMask = 0;
};
template <int D>
ProbeSite<D> probeSite(const ParticleSet<D>& particles, Index particle);
// The same for the probe's particle given as its site.
template <int D>
std::optional<LambReceiver> lambReceiver(const Scene& scene, const ProbeSite<D>& site, const Probe& probe);

// The exact response of a Lamb scene at its receivers.
class LambExactResponse {
 public:
  explicit LambExactResponse(const Scene& scene);  // lambReferenceUnavailable(scene) must be empty

  // Velocity (or displacement) at each of `times`. 2-D: LambStripLoad (about 1e-11). 3-D surface:
  // LambSquareLoad (about 1e-12). 3-D below the centre: f-k integration (about 1e-4 relative, a
  // second or two per receiver for 6 s) sampled every 1/64 and interpolated linearly (1e-5 of the
  // peak), computed up to `horizon` only (its cost grows with the square of the time span) and NaN
  // after it: pass the error window. The f-k series is kept per depth and span, so asking again
  // (the probes, then the fine grid of exact.csv) costs only the interpolation; not thread-safe.
  std::vector<Real> series(const LambReceiver& receiver, const std::vector<Real>& times, bool velocity,
                           Real horizon = std::numeric_limits<Real>::infinity()) const;

  // The 3-D surface solution (for the kernel-smoothed reference); null in 2-D.
  const LambSquareLoad* square() const { return square_ ? &*square_ : nullptr; }

 private:
  std::vector<Real> buriedSeries(Real depth, const std::vector<Real>& times, bool velocity, Real horizon) const;

  std::optional<LambSquareLoad> square_;             // 3-D, on the surface
  std::optional<HalfSpaceFrequencyWavenumber> buried_;  // 3-D, below the centre
  std::optional<LambStripLoad> strip_;               // 2-D, everywhere
  mutable std::map<std::pair<Real, Real>, HalfSpaceFrequencyWavenumber::Series> buriedCache_;  // (depth, end)
};

// The exact 3-D surface response to the load spread over the surface by the kernel: the square's
// response averaged over in-plane shifts z with the kernel's plane density int W(z, s) ds
// (normalised). A method whose surface tractions act through W cannot resolve the load more sharply
// than this, so its distance from the exact response is the part of an error the kernel's width
// alone explains.
std::vector<Real> kernelSmoothedLambSeries(const LambSquareLoad& exact, const Kernel& kernel,
                                           const std::array<Real, 2>& offset, const std::vector<Real>& times,
                                           bool velocity);

}  // namespace mfwave
