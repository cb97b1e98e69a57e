// libFuzzer target: a time-function CSV table (FuzzEntries.hpp). Built with -DMFWAVE_FUZZ=ON; run
// by scripts/run-fuzz.sh from the seed corpus data/tables.
#include "FuzzEntries.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  mfwave::fuzz::readTimeFunctionBytes(data, size);
  return 0;
}
