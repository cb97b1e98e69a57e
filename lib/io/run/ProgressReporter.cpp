#include "io/run/ProgressReporter.hpp"

#include "core/Error.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace mfwave {
namespace {

bool runningInCi() {
  const char* ci = std::getenv("CI");
  return ci && *ci && std::strcmp(ci, "false") != 0 && std::strcmp(ci, "0") != 0;
}

std::string duration(double seconds) {
  std::ostringstream s;
  if (seconds < 90) {
    s << std::fixed << std::setprecision(0) << seconds << " s";
  } else if (seconds < 5400) {
    s << std::fixed << std::setprecision(1) << seconds / 60 << " min";
  } else {
    s << std::fixed << std::setprecision(1) << seconds / 3600 << " h";
  }
  return s.str();
}

}  // namespace

ProgressReporter::ProgressReporter(Real endTime, Index particles, bool enabled)
    : endTime_(endTime), particles_(particles) {
  if (enabled && !runningInCi() && ::isatty(STDERR_FILENO)) out_ = &std::cerr;
}

ProgressReporter::ProgressReporter(Real endTime, Index particles, std::ostream& out, double minimumInterval)
    : endTime_(endTime), particles_(particles), out_(&out), minimumInterval_(minimumInterval) {}

void ProgressReporter::begin(const StateView& state) {
  startTime_ = state.time;
  startStep_ = state.step;
  rateTime_ = lastTime_ = state.time;
  rateStep_ = lastStep_ = state.step;
  wallStart_ = lastPrint_ = std::chrono::steady_clock::now();
}

void ProgressReporter::saveState(StateArchive& archive) const {
  archive.put("start", std::vector<Real>{startTime_, static_cast<Real>(startStep_)});
  archive.put("last", std::vector<Real>{lastTime_, static_cast<Real>(lastStep_)});
}

void ProgressReporter::restoreState(const StateArchive& archive) {
  const std::vector<Real>& start = archive.numbers("start", 2);
  startTime_ = start[0];
  startStep_ = static_cast<long>(start[1]);
  const std::vector<Real>& last = archive.numbers("last", 2);
  rateTime_ = lastTime_ = last[0];
  rateStep_ = lastStep_ = static_cast<long>(last[1]);
  wallStart_ = lastPrint_ = std::chrono::steady_clock::now();
}

std::string ProgressReporter::line(const StateView& state, double elapsed) const {
  const long steps = state.step - rateStep_;
  const Real done = state.time - rateTime_;  // since the wall clock started
  const Real total = endTime_ - startTime_;
  std::ostringstream s;
  s << "step " << state.step << "  t = " << std::setprecision(4) << state.time << " / " << endTime_;
  if (total > 0) s << "  (" << std::fixed << std::setprecision(0) << 100 * (state.time - startTime_) / total << " %)";
  if (elapsed > 0 && steps > 0) {
    s << std::scientific << std::setprecision(2) << "  "
      << static_cast<double>(particles_) * static_cast<double>(steps) / elapsed << " particle-steps/s";
    if (done > 0) s << "  left " << duration(elapsed * (endTime_ - state.time) / done);
  }
  return s.str();
}

void ProgressReporter::observe(const StateView& state) {
  lastTime_ = state.time;
  lastStep_ = state.step;
  if (!out_) return;
  const auto now = std::chrono::steady_clock::now();
  if (std::chrono::duration<double>(now - lastPrint_).count() < minimumInterval_) return;
  lastPrint_ = now;
  *out_ << '\r' << line(state, std::chrono::duration<double>(now - wallStart_).count()) << "\033[K" << std::flush;
}

void ProgressReporter::end(const StateView& state) {
  if (!out_) return;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart_).count();
  *out_ << '\r' << line(state, elapsed) << "\033[K\n" << std::flush;
}

}  // namespace mfwave
