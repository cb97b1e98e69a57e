#pragma once
// The one place that turns exceptions into exit codes and messages, so every driver fails alike:
//   0 success; 2 bad input (InputError, names the key); 3 the run became unstable
//   (InstabilityError, says where and when); 1 any other error; 128 + the signal (130 SIGINT,
//   143 SIGTERM) when an interruption ended the run early with its outputs written
//   (core/Interruption). Under --check, 0 once the scene and the plan are valid (CheckCompleted).

#include <functional>
#include <string>

namespace mfwave {

// Thrown by prepareOutputFolder under --check once the scene and the plan are read and valid:
// runDriver says so and returns 0. Not an error, so it derives from no exception class.
struct CheckCompleted {};

// `rank`: this process's rank in an MPI run (0 otherwise). Rank 0 speaks as a serial run does.
// Another rank names itself in its messages, says nothing of an interruption (the ranks agree on
// it, rank 0 reports it), and waits a second before reporting bad input: every rank reads the same
// scene and meets the same error, and rank 0's message with its abort of the job come first, so a
// user sees it once; an error of that rank's own is still printed after the wait.
int runDriver(const std::string& program, const std::function<int()>& body, int rank = 0);

}  // namespace mfwave
