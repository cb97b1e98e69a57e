#pragma once
// The time loop: advances an integrator to an end time and calls the observers every n steps.
// Drivers build the parts and hand them to a TimeLoop; nothing else steps a simulation.

#include "observers/Observer.hpp"

#include <functional>
#include <vector>

namespace mfwave {

struct RunStatistics {
  long steps = 0;
  Real startTime = 0;
  Real endTime = 0;
  double wallSeconds = 0;
  bool interrupted = false;  // SIGINT / SIGTERM ended the loop before endTime (core/Interruption)
  long resumedFromStep = -1;  // the checkpoint's step when the loop went on from one (else -1)
};

class TimeLoop {
 public:
  // `every` >= 1: the observer sees steps 0, every, 2 every, ... and the last step.
  void add(Observer& observer, long every = 1);

  // Steps until the integrator's time reaches endTime (within half a step). An InstabilityError
  // raised by an observer propagates at once: the run stops where it blew up. SIGINT or SIGTERM
  // ends the loop after the current step as if it were the last (observers see it, end() is
  // called, the statistics say `interrupted`).
  //
  // Checkpoints (core/CheckpointStore, when the driver installed one): before the first step the
  // integrator and every observer are saved once as a trial, so a part that cannot be
  // checkpointed is refused (InputError naming the store's setting) before any work; then the
  // loop writes a checkpoint every N steps and every T wall-clock seconds, and always when it ends
  // or is interrupted (after the last step, before the closing observations). When the store holds
  // a checkpoint of this loop, the integrator and the observers are restored from it in place of
  // begin(), and the loop goes on from its step: statistics count the steps from the original
  // start, so the run reads as one.
  RunStatistics run(Integrator& integrator, Real endTime);

  // For a loop whose integrator steps a system split over ranks (every rank runs the same loop):
  // `agree` replaces each value of a small array by its maximum over the ranks (collective). At
  // every step boundary the loop agrees on whether a signal asked to stop and on whether a
  // wall-clock checkpoint is due, so every rank stops, or writes its share of a checkpoint, after
  // the same step: a rank that stopped alone would leave the others waiting in a halo exchange. A
  // rank that received no signal raises the agreed one (requestInterruption), so it stops too.
  using Agreement = std::function<void(int* values, int count)>;
  void agreeAcrossRanks(Agreement agree) { agree_ = std::move(agree); }

 private:
  void restore(Integrator& integrator, const StateArchive& archive, long& firstStep, Real& startTime);
  StateArchive save(const Integrator& integrator, long firstStep, Real startTime) const;

  struct Entry {
    Observer* observer;
    long every;
  };
  std::vector<Entry> observers_;
  Agreement agree_;
};

}  // namespace mfwave
