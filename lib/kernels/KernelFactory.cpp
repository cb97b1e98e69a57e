#include "kernels/KernelFactory.hpp"

#include "core/Error.hpp"
#include "kernels/CubicBSplineKernel.hpp"
#include "kernels/CubicSplineKernel.hpp"
#include "kernels/GaussianKernel.hpp"
#include "kernels/QuinticSplineKernel.hpp"
#include "kernels/WendlandC2Kernel.hpp"
#include "kernels/WendlandC4Kernel.hpp"

namespace mfwave {

const std::vector<std::string>& kernelNames() {
  static const std::vector<std::string> names = {"cubic_spline", "gaussian",    "quintic_spline",
                                                 "wendland_c2",  "wendland_c4", "cubic_b_spline"};
  return names;
}

std::unique_ptr<Kernel> makeKernel(const std::string& name, int dimension, Real length) {
  if (name == "cubic_spline") return std::make_unique<CubicSplineKernel>(dimension, length);
  if (name == "gaussian") return std::make_unique<GaussianKernel>(dimension, length);
  if (name == "quintic_spline") return std::make_unique<QuinticSplineKernel>(dimension, length);
  if (name == "wendland_c2") return std::make_unique<WendlandC2Kernel>(dimension, length);
  if (name == "wendland_c4") return std::make_unique<WendlandC4Kernel>(dimension, length);
  if (name == "cubic_b_spline") return std::make_unique<CubicBSplineKernel>(dimension, length);

  std::string valid;
  for (const std::string& n : kernelNames()) valid += (valid.empty() ? "" : ", ") + n;
  throw InputError("kernel", "unknown kernel '" + name + "'; valid: " + valid);
}

}  // namespace mfwave
