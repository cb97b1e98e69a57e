#include "observers/GroupMeanRecorder.hpp"

#include "core/Error.hpp"

#include <cmath>

namespace mfwave {
namespace {

// Checks the component count first: it sizes the column names (the series is built before the
// constructor's body runs).
std::vector<std::string> columnNames(int components) {
  if (components < 1 || components > 3)
    throw InputError("components", "must be 1, 2 or 3, got " + std::to_string(components));
  const char* axis[3] = {"x", "y", "z"};
  std::vector<std::string> names;
  for (int c = 0; c < components; ++c) names.push_back(std::string("u_") + axis[c] + " [m]");
  for (int c = 0; c < components; ++c) names.push_back(std::string("v_") + axis[c] + " [m/s]");
  return names;
}

}  // namespace

GroupMeanRecorder::GroupMeanRecorder(std::string group, std::vector<Index> members, int components)
    : group_(std::move(group)),
      members_(std::move(members)),
      components_(components),
      series_("t [s]", columnNames(components)) {
  if (members_.empty()) throw InputError(group_, "a group mean needs at least one particle");
}

void GroupMeanRecorder::observe(const StateView& state) {
  if (series_.rows() > 0 && state.time <= series_.times().back()) return;  // already recorded
  const int d = components_;
  std::vector<Real> mean(static_cast<std::size_t>(2 * d), 0.0);
  for (const Index i : members_)  // summed in member order: the same result on any thread count
    for (int c = 0; c < d; ++c) {
      mean[static_cast<std::size_t>(c)] += state.displacement[i * d + c];
      mean[static_cast<std::size_t>(d + c)] += state.velocity[i * d + c];
    }
  for (Real& value : mean) {
    value /= static_cast<Real>(members_.size());
    if (!std::isfinite(value))
      throw InstabilityError("the mean displacement or velocity of " + group_ + " is not finite at t = " +
                                 std::to_string(state.time) + " (step " + std::to_string(state.step) + ")",
                             state.step, state.time, -1);
  }
  series_.append(state.time, mean);
}

void GroupMeanRecorder::end(const StateView& state) { observe(state); }

}  // namespace mfwave
