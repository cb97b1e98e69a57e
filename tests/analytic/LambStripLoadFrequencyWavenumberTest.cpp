// The exact 2-D Lamb solution (Cagniard-de Hoop, LambStripLoad) against the independent
// frequency-wavenumber integration (HalfSpaceFrequencyWavenumber, FFTW) at the 2-D study's three
// receivers: the load centre, the surface 2 from it, and depth 1 below it. The two share only the
// load: one deforms contours in the slowness plane and takes the Rayleigh pole as a principal
// value, the other sums the transfer function on a damped Bromwich line. Their agreement checks
// the contour deformation, the branches, the pole and head-wave terms and the plane wave's pole.

#include "analytic/HalfSpaceFrequencyWavenumber.hpp"
#include "analytic/LambStripLoad.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace mfwave;

namespace {
struct CrossCheck {
  double velocity, displacement;  // relative L2 over 0 <= t <= 6
};

CrossCheck compare(double x, double depth) {
  const LambStripLoad exact = LambStripLoad::dingLongWu();
  const HalfSpaceFrequencyWavenumber fk(1, 1, 1, SurfaceLoadShape::Strip, 0.5, {0, 1, 2}, {0, 1, 0});
  const auto series = fk.response(x, depth, 6, 1.0 / 64);
  double dv = 0, nv = 0, du = 0, nu = 0;
  for (std::size_t j = 0; j < series.time.size(); ++j) {
    const double t = series.time[j];
    const double v = exact.velocity(x, depth, t), u = exact.displacement(x, depth, t);
    dv += std::pow(series.velocity[j] - v, 2);
    nv += v * v;
    du += std::pow(series.displacement[j] - u, 2);
    nu += u * u;
  }
  return {std::sqrt(dv / nv), std::sqrt(du / nu)};
}
}  // namespace

TEST(LambStripLoadAgainstFrequencyWavenumber, AgreeAtTheStudysReceivers) {
  struct Receiver {
    double x, depth;
  };
  for (const Receiver& r : {Receiver{0, 0}, Receiver{2, 0}, Receiver{0, 1}, Receiver{2, 0.5}}) {
    const CrossCheck c = compare(r.x, r.depth);
    std::printf("x = %g, depth = %g: relative L2 velocity %.2e, displacement %.2e\n", r.x, r.depth, c.velocity,
                c.displacement);
    EXPECT_LT(c.velocity, 2e-4) << r.x << " " << r.depth;  // measured 6e-6 .. 1.3e-4
    EXPECT_LT(c.displacement, 2e-6) << r.x << " " << r.depth;  // measured 5e-9 .. 4e-7
  }
}
