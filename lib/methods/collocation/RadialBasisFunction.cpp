#include "methods/collocation/RadialBasisFunction.hpp"

#include <cmath>
#include <sstream>

#include "core/Error.hpp"

namespace mfwave {

const std::vector<std::string>& radialBasisNames() {
  static const std::vector<std::string> names = {"inverse_multiquadric", "multiquadric", "gaussian"};
  return names;
}

const char* radialBasisName(RadialBasisKind kind) {
  switch (kind) {
    case RadialBasisKind::InverseMultiquadric:
      return "inverse_multiquadric";
    case RadialBasisKind::Multiquadric:
      return "multiquadric";
    case RadialBasisKind::Gaussian:
      return "gaussian";
  }
  return "unknown";
}

RadialBasisKind radialBasisKind(const std::string& name) {
  const std::vector<std::string>& names = radialBasisNames();
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (names[k] == name) return static_cast<RadialBasisKind>(k);
  }
  std::string valid;
  for (const std::string& n : names) valid += (valid.empty() ? "" : ", ") + n;
  throw InputError("method.basis", "unknown radial basis function '" + name + "'; valid: " + valid);
}

RadialBasisFunction::RadialBasisFunction(RadialBasisKind kind, Real shapeParameter)
    : kind_(kind), c_(shapeParameter), c2_(shapeParameter * shapeParameter) {
  if (!(shapeParameter > 0) || !std::isfinite(shapeParameter) || !(c2_ > 0) || !std::isfinite(c2_)) {
    std::ostringstream text;
    text << "the shape parameter c of the " << radialBasisName(kind) << " basis must be positive and finite, got "
         << shapeParameter;
    throw InputError("method.shape_parameter", text.str());
  }
}

RadialBasisFunction::Profile RadialBasisFunction::profile(Real s) const {
  switch (kind_) {
    case RadialBasisKind::InverseMultiquadric: {
      // f = (s + c^2)^(-1/2), f' = -1/2 (s + c^2)^(-3/2), f'' = 3/4 (s + c^2)^(-5/2)
      const Real t = 1 / (s + c2_);
      const Real f = std::sqrt(t);
      return {f, -0.5 * f * t, 0.75 * f * t * t};
    }
    case RadialBasisKind::Multiquadric: {
      // f = (s + c^2)^(1/2), f' = 1/2 (s + c^2)^(-1/2), f'' = -1/4 (s + c^2)^(-3/2)
      const Real f = std::sqrt(s + c2_);
      const Real t = 1 / (s + c2_);
      return {f, 0.5 * f * t, -0.25 * f * t * t};
    }
    case RadialBasisKind::Gaussian: {
      // f = exp(-s / c^2), f' = -f / c^2, f'' = f / c^4
      const Real inv = 1 / c2_;
      const Real f = std::exp(-s * inv);
      return {f, -f * inv, f * inv * inv};
    }
  }
  return {0, 0, 0};
}

RadialBasisFunction makeRadialBasisFunction(const std::string& name, Real shapeParameter) {
  return RadialBasisFunction(radialBasisKind(name), shapeParameter);
}

}  // namespace mfwave
