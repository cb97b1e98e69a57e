// libFuzzer target: scene text and --set overrides (FuzzEntries.hpp). Built with -DMFWAVE_FUZZ=ON;
// run by scripts/run-fuzz.sh from the seed corpus data/scenes.
#include "FuzzEntries.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  mfwave::fuzz::readSceneBytes(data, size);
  return 0;
}
