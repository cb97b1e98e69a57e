#include "kernels/Kernel.hpp"

#include "core/Error.hpp"

#include <cmath>
#include <string>

namespace mfwave {

namespace {

int checkedDimension(int dimension) {
  if (dimension < 1 || dimension > 3)
    throw InputError("dimension", "kernel dimension must be 1, 2 or 3, got " + std::to_string(dimension));
  return dimension;
}

Real checkedLength(Real length, const char* key) {
  if (!(length > 0.0) || !std::isfinite(length))
    throw InputError(key, "must be positive and finite, got " + std::to_string(length));
  return length;
}

}  // namespace

Kernel::Kernel(int dimension, Real length, Real supportFactor, const std::array<Real, 3>& sigmaByDimension,
               const char* lengthKey)
    : dimension_(checkedDimension(dimension)),
      h_(checkedLength(length, lengthKey)),
      invH_(1.0 / length),
      kappa_(supportFactor),
      supportRadius_(supportFactor * length),
      supportRadius2_(supportRadius_ * supportRadius_),
      sigma_(sigmaByDimension[static_cast<std::size_t>(dimension - 1)]),
      valueScale_(sigma_ / std::pow(length, dimension)),
      derivativeScale_(sigma_ / std::pow(length, dimension + 2)) {}

void Kernel::throwDimensionMismatch(int d) const {
  throw InputError("dimension", std::string(name()) + " kernel was built for " + std::to_string(dimension_) +
                                    "-D but evaluated with a " + std::to_string(d) + "-D vector");
}

}  // namespace mfwave
