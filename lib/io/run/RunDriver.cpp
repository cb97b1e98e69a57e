#include "io/run/RunDriver.hpp"

#include "core/CheckpointStore.hpp"
#include "core/Error.hpp"
#include "core/Interruption.hpp"

#include <chrono>
#include <csignal>
#include <exception>
#include <iostream>
#include <string>
#include <thread>

namespace mfwave {

int runDriver(const std::string& program, const std::function<int()>& body, int rank) {
  const std::string who = rank > 0 ? program + " (rank " + std::to_string(rank) + ")" : program;
  // A file that outgrows RLIMIT_FSIZE (a quota, a small filesystem limit) would kill the process
  // with SIGXFSZ mid-write; ignored, the write fails instead and the writer reports it (exit 1,
  // naming the file, the temporary removed).
  std::signal(SIGXFSZ, SIG_IGN);
  try {
    const int status = body();
    if (interruptionRequested()) {
      if (rank > 0) return 128 + interruptionSignal();
      std::cerr << program << ": interrupted by " << interruptionSignalName()
                << ": the outputs of the steps taken are written (summary.json says where the run stopped)";
      if (const CheckpointStore* store = checkpointStore(); store && !store->folder().empty())
        std::cerr << "; a checkpoint of the step it reached too: go on with " << program << " --restart "
                  << store->folder();
      std::cerr << '\n';
      return 128 + interruptionSignal();
    }
    return status;
  } catch (const CheckCompleted&) {
    if (rank == 0)
      std::cout << program << ": the scene is valid (every key read, the plan accepted; --check: nothing run or "
                              "written)\n";
    return 0;
  } catch (const InputError& e) {
    if (rank > 0) std::this_thread::sleep_for(std::chrono::seconds(1));
    std::cerr << who << ": error: " << e.what() << '\n';
    return 2;
  } catch (const InstabilityError& e) {
    std::cerr << who << ": run stopped: " << e.what() << '\n';
    return 3;
  } catch (const Error& e) {
    std::cerr << who << ": error: " << e.what() << '\n';
    return 1;
  } catch (const std::exception& e) {
    std::cerr << who << ": internal error: " << e.what() << '\n';
    return 1;
  }
}

}  // namespace mfwave
