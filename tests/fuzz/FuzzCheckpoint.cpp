// libFuzzer target: a checkpoint file (FuzzEntries.hpp). Built with -DMFWAVE_FUZZ=ON; run by
// scripts/run-fuzz.sh from the seed corpus tests/fuzz/seeds/checkpoint.
#include "FuzzEntries.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  mfwave::fuzz::readCheckpointBytes(data, size);
  return 0;
}
