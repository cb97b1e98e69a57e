#pragma once
// A clean stop on SIGINT (Ctrl-C) or SIGTERM (a scheduler's kill) while a run steps. A guard lives
// for the duration of a time loop: the first signal only raises a flag, the loop ends after the
// step it is in as if it had reached its end (every observer sees that state and writes its
// output), later cases of a study are not started, the summary says where the run stopped, and the
// program exits with 128 + the signal (130, 143), the shell's convention. The first signal also
// restores the signal's default action, so a second one kills at once. Outside a guard the signals
// keep their default action (nothing partial to save).

namespace mfwave {

class InterruptionGuard {
 public:
  InterruptionGuard();   // installs the handlers (nested guards leave the outer one's in place)
  ~InterruptionGuard();  // restores the previous actions
  InterruptionGuard(const InterruptionGuard&) = delete;
  InterruptionGuard& operator=(const InterruptionGuard&) = delete;
};

// The signal that asked the run to stop (SIGINT or SIGTERM), 0 if none has. Stays set for the rest
// of the process.
int interruptionSignal();
inline bool interruptionRequested() { return interruptionSignal() != 0; }
// "SIGINT", "SIGTERM" or "a signal".
const char* interruptionSignalName();

// Raises the flag as the signal's handler would (a no-op when one is already raised): how the
// ranks of a run that agreed to stop (TimeLoop::agreeAcrossRanks) all stop alike, also those
// that received no signal themselves.
void requestInterruption(int signal);

// For tests: forget a past interruption.
void clearInterruption();

}  // namespace mfwave
