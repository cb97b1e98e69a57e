#include "io/run/RunDriver.hpp"

#include "core/Error.hpp"
#include "core/Interruption.hpp"

#include <exception>
#include <iostream>

namespace mfwave {

int runDriver(const std::string& program, const std::function<int()>& body) {
  try {
    const int status = body();
    if (interruptionRequested()) {
      std::cerr << program << ": interrupted by " << interruptionSignalName()
                << ": the outputs of the steps taken are written (summary.json says where the run stopped)\n";
      return 128 + interruptionSignal();
    }
    return status;
  } catch (const InputError& e) {
    std::cerr << program << ": error: " << e.what() << '\n';
    return 2;
  } catch (const InstabilityError& e) {
    std::cerr << program << ": run stopped: " << e.what() << '\n';
    return 3;
  } catch (const Error& e) {
    std::cerr << program << ": error: " << e.what() << '\n';
    return 1;
  } catch (const std::exception& e) {
    std::cerr << program << ": internal error: " << e.what() << '\n';
    return 1;
  }
}

}  // namespace mfwave
