#pragma once
// Element-wise updates of state vectors, OpenMP-parallel above a size where threads pay off. Each
// entry is computed alone, so the results are bitwise the same on any thread count. The explicit
// integrators' kicks and drifts use them: on a matrix-free operator the step's vector passes cost
// as much as the operator, and Eigen runs them on one thread.

#include "core/Types.hpp"

namespace mfwave {

// y += s x
void addScaled(Vector& y, Real s, const Vector& x);
// y = a + s b (y may alias a or b)
void assignSum(Vector& y, const Vector& a, Real s, const Vector& b);
// y = x (y resized)
void assignCopy(Vector& y, const Vector& x);

}  // namespace mfwave
