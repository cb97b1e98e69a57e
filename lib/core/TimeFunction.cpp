#include "core/TimeFunction.hpp"

#include "core/BoundedRead.hpp"
#include "core/Error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace mfwave {
namespace {

std::string number(Real x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

void requireFinite(const std::string& key, Real x) {
  if (!std::isfinite(x)) throw InputError(key, "must be a finite number, got " + number(x));
}

void requirePositive(const std::string& key, Real x) {
  requireFinite(key, x);
  if (!(x > 0)) throw InputError(key, "must be positive, got " + number(x));
}

}  // namespace

TimeFunction TimeFunction::constant(Real value) {
  requireFinite("value", value);
  return TimeFunction(Kind::Constant, {value});
}

TimeFunction TimeFunction::ramp(Real start, Real duration, Real amplitude) {
  requireFinite("start", start);
  requirePositive("duration", duration);
  requireFinite("amplitude", amplitude);
  return TimeFunction(Kind::Ramp, {start, duration, amplitude});
}

TimeFunction TimeFunction::triangle(Real start, Real rise, Real fall, Real amplitude) {
  requireFinite("start", start);
  requirePositive("rise", rise);
  requirePositive("fall", fall);
  requireFinite("amplitude", amplitude);
  return TimeFunction(Kind::Triangle, {start, rise, fall, amplitude});
}

TimeFunction TimeFunction::ricker(Real peakFrequency, Real delay, Real amplitude) {
  requirePositive("peak_frequency", peakFrequency);
  requireFinite("delay", delay);
  requireFinite("amplitude", amplitude);
  return TimeFunction(Kind::Ricker, {peakFrequency, delay, amplitude});
}

TimeFunction TimeFunction::tabulated(std::vector<Real> times, std::vector<Real> values) {
  if (times.size() != values.size())
    throw InputError("values", "needs one value per time (" + std::to_string(times.size()) + " times, " +
                                   std::to_string(values.size()) + " values)");
  if (times.size() < 2) throw InputError("times", "needs at least 2 points");
  for (std::size_t i = 0; i < times.size(); ++i) {
    requireFinite("times[" + std::to_string(i) + "]", times[i]);
    requireFinite("values[" + std::to_string(i) + "]", values[i]);
    if (i > 0 && !(times[i] > times[i - 1]))
      throw InputError("times[" + std::to_string(i) + "]", "times must increase strictly");
  }
  TimeFunction f(Kind::Tabulated, {});
  f.times_ = std::move(times);
  f.values_ = std::move(values);
  return f;
}

TimeFunction TimeFunction::fromCsv(const std::string& path) {
  return fromCsvText(readBoundedFile(path, kMaxTableBytes, "file", "the time-function table"), path);
}

TimeFunction TimeFunction::fromCsvText(const std::string& text, const std::string& path) {
  std::istringstream in(text);
  std::vector<Real> times, values;
  std::string line;
  int lineNumber = 0;
  while (std::getline(in, line)) {
    ++lineNumber;
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    Real t, v;
    std::string rest;
    if (!(fields >> t >> v)) {
      if (times.empty() && values.empty()) continue;  // one header line before the data
      throw InputError("file", "'" + path + "' line " + std::to_string(lineNumber) +
                                   ": expected two numbers (time, value)");
    }
    if (fields >> rest)
      throw InputError("file", "'" + path + "' line " + std::to_string(lineNumber) + ": more than two columns");
    times.push_back(t);
    values.push_back(v);
  }
  try {
    TimeFunction f = tabulated(std::move(times), std::move(values));
    f.source_ = path;
    return f;
  } catch (const InputError& e) {
    throw InputError("file", "'" + path + "': " + e.what());
  }
}

Real TimeFunction::operator()(Real t) const {
  switch (kind_) {
    case Kind::Constant:
      return p_[0];
    case Kind::Ramp: {
      const Real s = (t - p_[0]) / p_[1];
      return p_[2] * std::clamp(s, Real(0), Real(1));
    }
    case Kind::Triangle: {
      const Real s = t - p_[0];
      if (s <= 0 || s >= p_[1] + p_[2]) return 0;
      return s <= p_[1] ? p_[3] * s / p_[1] : p_[3] * (p_[1] + p_[2] - s) / p_[2];
    }
    case Kind::Ricker: {
      const Real a = std::pow(kPi * p_[0] * (t - p_[1]), 2);
      return p_[2] * (1 - 2 * a) * std::exp(-a);
    }
    case Kind::Tabulated: {
      if (t <= times_.front()) return values_.front();
      if (t >= times_.back()) return values_.back();
      const auto upper = std::upper_bound(times_.begin(), times_.end(), t);
      const std::size_t i = static_cast<std::size_t>(upper - times_.begin());
      const Real w = (t - times_[i - 1]) / (times_[i] - times_[i - 1]);
      return (1 - w) * values_[i - 1] + w * values_[i];
    }
  }
  return 0;
}

bool TimeFunction::piecewiseLinear(std::vector<Real>& times, std::vector<Real>& values) const {
  switch (kind_) {
    case Kind::Ramp:
      times = {p_[0], p_[0] + p_[1]};
      values = {0, p_[2]};
      return true;
    case Kind::Triangle:
      times = {p_[0], p_[0] + p_[1], p_[0] + p_[1] + p_[2]};
      values = {0, p_[3], 0};
      return true;
    case Kind::Tabulated:
      times = times_;
      values = values_;
      return true;
    default:
      return false;
  }
}

Real TimeFunction::quietAfter() const {
  constexpr Real never = std::numeric_limits<Real>::infinity();
  switch (kind_) {
    case Kind::Constant:
      return p_[0] == 0 ? -never : never;
    case Kind::Ramp:
      return p_[2] == 0 ? -never : never;
    case Kind::Triangle:
      return p_[3] == 0 ? -never : p_[0] + p_[1] + p_[2];
    case Kind::Ricker:
      // |f| / amplitude = |1 - 2a| e^{-a} < 1e-30 once a = (pi f tau)^2 > 73, i.e. tau > 2.72 / f.
      return p_[2] == 0 ? -never : p_[1] + 3 / p_[0];
    case Kind::Tabulated: {
      if (values_.back() != 0) return never;
      std::size_t last = values_.size() - 1;  // the first breakpoint of the trailing run of zeros
      while (last > 0 && values_[last - 1] == 0) --last;
      return last == 0 ? -never : times_[last];
    }
  }
  return never;
}

std::string TimeFunction::describe() const {
  switch (kind_) {
    case Kind::Constant:
      return "constant(value=" + number(p_[0]) + ")";
    case Kind::Ramp:
      return "ramp(start=" + number(p_[0]) + ", duration=" + number(p_[1]) + ", amplitude=" + number(p_[2]) + ")";
    case Kind::Triangle:
      return "triangle(start=" + number(p_[0]) + ", rise=" + number(p_[1]) + ", fall=" + number(p_[2]) +
             ", amplitude=" + number(p_[3]) + ")";
    case Kind::Ricker:
      return "ricker(peak_frequency=" + number(p_[0]) + ", delay=" + number(p_[1]) + ", amplitude=" + number(p_[2]) +
             ")";
    case Kind::Tabulated:
      return "tabulated(" + std::to_string(times_.size()) + " points" + (source_.empty() ? "" : " from " + source_) +
             ")";
  }
  return "";
}

}  // namespace mfwave
