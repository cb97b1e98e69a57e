#include "core/Interruption.hpp"

#include <csignal>

namespace mfwave {
namespace {

volatile std::sig_atomic_t requested = 0;
int depth = 0;  // nested guards: only the outermost installs and restores
struct sigaction previousInt, previousTerm;

extern "C" void onInterruption(int signal) {
  requested = signal;
  std::signal(signal, SIG_DFL);  // a second signal kills at once
}

}  // namespace

InterruptionGuard::InterruptionGuard() {
  if (depth++ > 0) return;
  struct sigaction action {};
  action.sa_handler = onInterruption;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;
  sigaction(SIGINT, &action, &previousInt);
  sigaction(SIGTERM, &action, &previousTerm);
}

InterruptionGuard::~InterruptionGuard() {
  if (--depth > 0) return;
  sigaction(SIGINT, &previousInt, nullptr);
  sigaction(SIGTERM, &previousTerm, nullptr);
}

int interruptionSignal() { return static_cast<int>(requested); }

const char* interruptionSignalName() {
  switch (interruptionSignal()) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    default:
      return "a signal";
  }
}

void requestInterruption(int signal) {
  if (requested == 0 && signal != 0) requested = signal;
}

void clearInterruption() { requested = 0; }

}  // namespace mfwave
