#pragma once
// The time loop: advances an integrator to an end time and calls the observers every n steps.
// Drivers build the parts and hand them to a TimeLoop; nothing else steps a simulation.

#include "observers/Observer.hpp"

#include <vector>

namespace mfwave {

struct RunStatistics {
  long steps = 0;
  Real startTime = 0;
  Real endTime = 0;
  double wallSeconds = 0;
  bool interrupted = false;  // SIGINT / SIGTERM ended the loop before endTime (core/Interruption)
};

class TimeLoop {
 public:
  // `every` >= 1: the observer sees steps 0, every, 2 every, ... and the last step.
  void add(Observer& observer, long every = 1);

  // Steps until the integrator's time reaches endTime (within half a step). An InstabilityError
  // raised by an observer propagates at once: the run stops where it blew up. SIGINT or SIGTERM
  // ends the loop after the current step as if it were the last (observers see it, end() is
  // called, the statistics say `interrupted`).
  RunStatistics run(Integrator& integrator, Real endTime);

 private:
  struct Entry {
    Observer* observer;
    long every;
  };
  std::vector<Entry> observers_;
};

}  // namespace mfwave
