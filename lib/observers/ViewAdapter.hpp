#pragma once
// An observer that shows other observers another view of the state, each at its own interval.
//
// A first-order system hands its observers its whole state; the particle observers (frames,
// probes, the stability monitor) want particles at their current positions with a displacement
// and a velocity. An adapter forms that view (`adapt`) and forwards it. Each observer added here
// keeps its own interval, counted in steps as TimeLoop counts them, and the view is formed only on
// the steps when one of them is due: one adapter serves every output of a run, with one copy of
// the particles, whatever their intervals.
//
// Add the adapter itself to the TimeLoop at every step (the default interval), so that it sees
// each step its observers may be due at.

#include "observers/Observer.hpp"

#include <vector>

namespace mfwave {

class ViewAdapter : public Observer {
 public:
  // `every` >= 1: the observer sees steps 0, every, 2 every, ... and the last step. It must
  // outlive the adapter's use.
  void add(Observer& observer, long every = 1);

  void begin(const StateView& state) override;
  void observe(const StateView& state) override;
  void end(const StateView& state) override;
  // The step its intervals count from, and each observer's own state in section "o<k>" (k in the
  // order added). The view itself is formed anew from the state at every due step: nothing of it
  // is kept.
  void saveState(StateArchive& archive) const override;
  void restoreState(const StateArchive& archive) override;

 protected:
  // The view shown to the observers; it may refer to the adapter's own storage until the next call.
  virtual StateView adapt(const StateView& state) = 0;

 private:
  struct Entry {
    Observer* observer;
    long every;
  };
  std::vector<Entry> observers_;
  long firstStep_ = 0;
};

}  // namespace mfwave
