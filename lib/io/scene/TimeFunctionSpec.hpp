#pragma once
// A time_function table anywhere in a scene ("load[0].time_function"): its type and the
// parameters of core/TimeFunction.hpp, built into a TimeFunction. Errors of the TimeFunction
// factories are reported at the parameter's full key path ("load[0].time_function.duration").
//
//   constant   value (1)
//   ramp       start (0), duration (required), amplitude (1)
//   triangle   start (0), rise (required), fall (= rise), amplitude (1)
//   ricker     peak_frequency (required), delay (1.5 / peak_frequency), amplitude (1)
//   tabulated  times and values, or file (CSV, relative to the scene file's folder; written
//              as an absolute path into the resolved scene)

#include "core/TimeFunction.hpp"
#include "io/scene/SceneReader.hpp"

#include <string>

namespace mfwave {

// The default delay of a Ricker wavelet, in periods 1 / peak_frequency: the wavelet is then
// within 1e-8 of its amplitude of zero at t = 0, so a run starting at rest sees no jump.
constexpr Real kRickerDelayPeriods = 1.5;

// When the table is absent: a "missing required key" error if `required`, else constant 1
// (inserted into the resolved scene).
TimeFunction readTimeFunction(SceneReader& reader, const std::string& path, bool required);

}  // namespace mfwave
