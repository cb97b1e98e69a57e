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

void ViewAdapter::saveState(StateArchive& archive) const {
  archive.put("adapter", std::vector<Real>{static_cast<Real>(firstStep_), static_cast<Real>(observers_.size())});
  for (std::size_t k = 0; k < observers_.size(); ++k) {
    StateArchive part = archive.section("o" + std::to_string(k));
    observers_[k].observer->saveState(part);
  }
}

void ViewAdapter::restoreState(const StateArchive& archive) {
  const std::vector<Real>& adapter = archive.get("adapter");
  if (adapter.size() != 2 || adapter[1] != static_cast<Real>(observers_.size()))
    throw InputError("--restart", "the checkpoint's view adapter had another set of observers than this run's (" +
                                      std::to_string(observers_.size()) + ")");
  firstStep_ = static_cast<long>(adapter[0]);
  for (std::size_t k = 0; k < observers_.size(); ++k)
    observers_[k].observer->restoreState(archive.section("o" + std::to_string(k)));
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
