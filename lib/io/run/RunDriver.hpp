#pragma once
// The one place that turns exceptions into exit codes and messages, so every driver fails alike:
//   0 success; 2 bad input (InputError, names the key); 3 the run became unstable
//   (InstabilityError, says where and when); 1 any other error; 128 + the signal (130 SIGINT,
//   143 SIGTERM) when an interruption ended the run early with its outputs written
//   (core/Interruption).

#include <functional>
#include <string>

namespace mfwave {

int runDriver(const std::string& program, const std::function<int()>& body);

}  // namespace mfwave
