#pragma once
// Builds a kernel from its scene name, so scenes and drivers never name concrete classes.

#include "kernels/Kernel.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mfwave {

// Names accepted by makeKernel, in a fixed order (for help texts and error messages).
const std::vector<std::string>& kernelNames();

// name: "cubic_spline", "gaussian", "quintic_spline", "wendland_c2", "wendland_c4",
// "cubic_b_spline". length is the smoothing length h, except for "cubic_b_spline", where it is the
// support radius a (Luo-Liu-Huang eq. (6)). Throws InputError with key "kernel" (unknown name),
// "dimension" (not 1..3), "smoothing_length" / "support_radius" (length not positive).
std::unique_ptr<Kernel> makeKernel(const std::string& name, int dimension, Real length);

}  // namespace mfwave
