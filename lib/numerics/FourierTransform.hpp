#pragma once
// The one place that calls FFTW: in-place forward discrete Fourier transforms of complex data,
//   X(m) = sum_n x(n) exp(-2 pi i m . n / N),
// on a cube of N^rank points stored with the first index fastest (the transform is the same for
// either storage order because every axis has N points). FFTW's planner is not thread-safe, so
// planning is serialised here; executing a plan is.

#include "core/Types.hpp"

#include <complex>
#include <vector>

namespace mfwave {

using ComplexVector = std::vector<std::complex<Real>>;

// Transforms `data` (N^rank values) in place. Throws InputError("cells") when the size is not
// N^rank, Error when FFTW cannot plan.
void forwardFourierTransform(ComplexVector& data, int rank, int cells);

}  // namespace mfwave
