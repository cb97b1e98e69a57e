#include "observers/ViewAdapter.hpp"

#include "core/Error.hpp"

#include <string>

namespace mfwave {

void ViewAdapter::add(Observer& observer, long every) {
  if (every < 1) throw InputError("output_every", "must be at least 1, got " + std::to_string(every));
  observers_.push_back({&observer, every});
}

void ViewAdapter::begin(const StateView& state) {
  firstStep_ = state.step;
  if (observers_.empty()) return;
  const StateView view = adapt(state);
  for (const Entry& e : observers_) e.observer->begin(view);
}

void ViewAdapter::observe(const StateView& state) {
  const long n = state.step - firstStep_;
  bool due = false;
  for (const Entry& e : observers_) due = due || n % e.every == 0;
  if (!due) return;  // nobody is due: no view formed
  const StateView view = adapt(state);
  for (const Entry& e : observers_)
    if (n % e.every == 0) e.observer->observe(view);
}

// As TimeLoop ends a run: the last step for those it was not due at, then end() for all.
void ViewAdapter::end(const StateView& state) {
  if (observers_.empty()) return;
  const long n = state.step - firstStep_;
  const StateView view = adapt(state);
  for (const Entry& e : observers_) {
    if (n % e.every != 0) e.observer->observe(view);
    e.observer->end(view);
  }
}

}  // namespace mfwave
