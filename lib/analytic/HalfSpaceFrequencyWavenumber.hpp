#pragma once
// Frequency-wavenumber (f-k) integration of the vertical response of a homogeneous elastic
// half-space z >= 0 (z the depth) to a uniform normal surface traction on a strip |x| < l (plane
// strain) or a square |x|, |y| < l (3-D). An independent reference for the exact Cagniard-de Hoop
// solutions (LambStripLoad, LambSquareLoad): it shares no formula with them beyond the load.
//
// Load and sign: the traction pushes INTO the solid, sigma_zz(x, 0, t) = -p f(t) X(x), X the
// indicator of the loaded region, f piecewise linear from f = 0 (PiecewiseLinearLoad); outputs are
// the vertical displacement and velocity POSITIVE INTO THE SOLID (along the applied traction).
//
// Formulas. Laplace variable s (Re s > 0), horizontal wavenumber k, u(x) = (1/2pi) int u~ e^{-ikx}:
//   nu_p = sqrt(k^2 + s^2/alpha^2), nu_s = sqrt(k^2 + s^2/beta^2)   (principal roots, Re >= 0),
//   D = (2k^2 + s^2/beta^2)^2 - 4 k^2 nu_p nu_s                      (Rayleigh function),
//   T(k, z, s) = nu_p [(2k^2 + s^2/beta^2) e^{-nu_p z} - 2k^2 e^{-nu_s z}] / (mu D),
//   u~_z = p F(s) Xhat(k) T,   F(s) = sum_k ds_k e^{-s t_k} / s^2  (ds_k: f's slope changes).
// At k = 0, T = e^{-s z/alpha} / (rho alpha s): the plane P wave. For k >> |s| the transfer tends
// to the quasi-static (Boussinesq) kernel T_0 = e^{-kz} [(lambda+2mu)/((lambda+mu) k) + z] / (2mu).
//   Strip:  Xhat = 2 sin(kl)/k,  u(x, z, s) = (1/pi) int_0^inf u~ cos(kx) dk.
//   Square: receivers on the axis x = y = 0 only,
//           u(0, 0, z, s) = (1/4pi^2) int_0^inf k A(k) T dk, A(k) = int_0^2pi Xhat(k cos th, k sin th) dth
//           (Xhat = [2 sin(k1 l)/k1][2 sin(k2 l)/k2]; each Fourier mode is a plane-strain problem).
// Time: Bromwich line s = eps + i omega, trapezoid in omega with a real inverse FFT (FFTW),
//   u(t_j) = e^{eps t_j} (1/T) sum_n W_n u(eps + i omega_n) e^{i omega_n t_j},  omega_n = 2 pi n / T,
// W_n = 1 but for a cosine roll-off over the top `taper` of the band. Velocity = s u(s) (u(0) = 0).
// The plane P wave under the load, p F e^{-sz/alpha} / (rho alpha s) for |x| < l (half of it at
// |x| = l), carries the kinks of f, the response's strongest singularities: it is subtracted from
// the spectrum and added back exactly in time, so the band limit does not smear them.
//
// Discretisation (FrequencyWavenumberSettings; the defaults give the accuracy quoted below):
// - Period T = periodFactor * endTime (4x), rounded up to an FFT-friendly length, and
//   eps = dampingPerPeriod / T (24 / T): later times wrap around damped by e^{-eps T} ~ 4e-11.
//   Errors that are irregular in omega spread over all times and grow like e^{eps t} (e^6 at
//   endTime); that, not the wrap-around, is why T is several times endTime rather than eps large.
// - Internal step h = dt / m, m the smallest integer with h <= tau / samplesPerTimeScale (32),
//   tau = min(l / alpha, shortest load segment): the output samples are exact FFT samples (every
//   m-th), not interpolated. The band ends at pi / h.
// - Strip: trapezoid in k, step dk = 2 pi / L, L = 1.25 alpha endTime + 2 (l + |x|). By Poisson
//   summation the sum over all nodes is exactly the problem periodic in x with period L, whose
//   images arrive after endTime (the integrand is even in k: no end correction at k = 0). The sum
//   is cut at K with the quasi-static integrand g_0 = Xhat cos(kx) T_0 / pi subtracted node by node
//   and the sum of g_0 over ALL nodes added in closed form (dilogarithm Li_2(e^{dk(ia - z)}),
//   a = l +- x): what is left out, g - g_0, is O(|s|^2/k^2) g_0. (The discrete tail, not the
//   integral of g_0 beyond K, is what completes the sum: with sin(ka) oscillating from node to
//   node the two differ at O(1).)
//   Square: k A(k) T is odd in k, so a trapezoid on [0, inf) would be only second order; instead
//   16-point Gauss-Legendre panels on a path lifted to Im k = 1/l: for omega >= 0 the branch
//   points and the Rayleigh pole, k = +-(omega - i eps)/c, lie in the 2nd and 4th quadrants, so
//   the 1st is analytic and Cauchy allows the lift, away from singularities only eps/c below the
//   real axis (panels 2x the distance to the nearest singularity: ~1e-13 per panel). A(k) (entire,
//   computed once per node at complex k) is a trapezoid in theta, exact once its points exceed
//   the angular band ~sqrt2 |k| l. Beyond K, at the surface, T -> c2 / (2 mu k) and the rest of
//   (1/4pi^2) int c2/(2mu) A dk along the path is the centre's static settlement
//   (int_0^inf A dk = 2 pi * 8 l ln(1 + sqrt 2)) less the path's quadrature so far.
// - Cut-off K(omega) = cutoffFactor (4) x (|s| / c_R + 16 max(1/l, eps/c_R)): the multiple of
//   |s| keeps g - g_0 small, the floor keeps K >> |s| at low frequencies and resolves Xhat. Below
//   the surface K = sqrt(|s|^2/beta^2 + (36/z)^2) (e^{-Re(nu) z} < e^{-36}), capped at the
//   surface's largest K for shallow receivers.
//
// Accuracy measured (tests/analytic/HalfSpaceFrequencyWavenumberTest.cpp and
// LambStripLoadFrequencyWavenumberTest.cpp; lambda = mu = rho = 1, l = 0.5, triangle load,
// 0 <= t <= 6, default settings, relative L2 error):
//   square, surface centre, against LambSquareLoad: velocity 4.9e-5, displacement 8.6e-7;
//   strip against LambStripLoad: velocity 2e-6 .. 2e-5 below the surface, 2.5e-5 .. 1.3e-4 on it,
//   displacement 1e-9 .. 4e-7; wide strip (l = 50): the plane wave to 5e-8 (surface) / 1e-14 (z = 1).
// On the surface the velocity error sits at the edges' Rayleigh arrivals (cusps that the band limit
// rounds); it falls with the internal step (x2 samples: 4.9e-5 -> 3e-5 for the square).
// Cost: (frequencies) x (wavenumbers per frequency), ~50 ns each. With endTime = 6, dt = 0.01:
// 0.5 s for the square's surface centre, 0.2-0.3 s per strip receiver (Release build).
// The square's A(k) costs ~|k| l per node: a square much wider than l ~ 1 becomes slow.

#include "analytic/PiecewiseLinearLoad.hpp"
#include "core/Types.hpp"

#include <vector>

namespace mfwave {

enum class SurfaceLoadShape { Strip, Square };

// Relative knobs of the discretisation (each has the meaning given in the header comment above),
// checked by the constructor (InputError "settings.<snake_case name>"). Convergence studies halve
// the steps (samplesPerTimeScale * 2, wavenumberSpacing / 2) and raise the cut-off (cutoffFactor * 2).
struct FrequencyWavenumberSettings {
  Real periodFactor = 4;           // T >= periodFactor * endTime (> 1)
  Real dampingPerPeriod = 24;      // eps * T (in [4, 60])
  Real samplesPerTimeScale = 32;   // h <= tau / samplesPerTimeScale (>= 4)
  Real taper = 0.1;                // fraction of the band rolled off by a cosine (in [0, 1))
  Real wavenumberSpacing = 1;      // scales dk (strip; > 1 would let images in) and the panels (square) (in (0, 1])
  Real cutoffFactor = 4;           // K(omega) = cutoffFactor (|s| / c_R + 16 max(1/l, eps/c_R)) (>= 0.5)
};

class HalfSpaceFrequencyWavenumber {
 public:
  // Lame lambda > -mu, mu > 0, rho > 0 (all finite), half-width l > 0, the load's breakpoints
  // (PiecewiseLinearLoad: times strictly increasing, at least 2, first value 0, constant after
  // the last), pressure amplitude p. Throws InputError naming the parameter ("lambda", "mu",
  // "rho", "half_width", "times", "values", "pressure", "settings.<name>").
  HalfSpaceFrequencyWavenumber(Real lambda, Real mu, Real rho, SurfaceLoadShape shape, Real halfWidth,
                               std::vector<Real> times, std::vector<Real> values, Real pressure = 1,
                               FrequencyWavenumberSettings settings = {});

  struct Series {
    std::vector<Real> time, displacement, velocity;
  };
  // Receiver at horizontal offset x from the load centre (strip: any x; square: x must be 0) and
  // depth >= 0; samples t_j = j dt, 0 <= t_j <= endTime (endTime > 0, 0 < dt <= endTime). Throws
  // InputError naming "x", "depth", "end_time" or "dt".
  Series response(Real x, Real depth, Real endTime, Real dt) const;

  Real pWaveSpeed() const { return alpha_; }
  Real shearWaveSpeed() const { return beta_; }
  Real rayleighWaveSpeed() const { return cR_; }

 private:
  Real lambda_, mu_, rho_, alpha_, beta_, cR_;
  SurfaceLoadShape shape_;
  Real l_, p_;
  PiecewiseLinearLoad load_;
  FrequencyWavenumberSettings settings_;
};

}  // namespace mfwave
