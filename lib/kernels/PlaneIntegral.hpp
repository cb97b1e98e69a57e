#pragma once
// Integral of the kernel over a hyperplane through its centre, int_plane W(x - y) dS_y.
//
// The very weak form SPH spreads boundary tractions with surface weights A_a whose scale S_a is
// fixed by S_a int_plane W dS = 1 (Ding-Long-Wu eq. (20)); for the 3-D cubic spline (38) this
// gives S_a = 10h/7 (eq. (40)), i.e. int_plane W dS = 7/(10h).

#include "kernels/Kernel.hpp"

namespace mfwave {

// For a d-D kernel, the (d-1)-D integral over the hyperplane through the centre:
//   3-D: 2 pi int_0^R s W(s) ds,  2-D: 2 int_0^R W(s) ds (a line),  1-D: W(0) (a point).
// Computed by Gauss-Legendre on each piece of the profile: exact to rounding for the splines,
// to ~1e-15 relative for the Gaussian.
Real planeIntegralThroughCentre(const Kernel& kernel);

}  // namespace mfwave
