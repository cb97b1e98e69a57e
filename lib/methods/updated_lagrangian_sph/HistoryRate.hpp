#pragma once
// The time derivative of a load history, for prescribed velocities: the acceleration of a
// particle whose velocity is v(t) = velocity * history(t) is velocity * history'(t).

#include "core/TimeFunction.hpp"
#include "core/Types.hpp"

namespace mfwave {

// history'(t). Piecewise-linear histories (constant, ramp, triangle, tabulated) give the exact
// slope of the piece that starts at t (the right-hand slope at a breakpoint, which is what an
// explicit step starting at t integrates); others (Ricker) a central difference with step
// 1e-6 max(1, |t|), accurate to about 1e-10 relative for the smooth wavelets used here.
Real historyRate(const TimeFunction& history, Real t);

}  // namespace mfwave
