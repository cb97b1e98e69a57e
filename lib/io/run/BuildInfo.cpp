#include "io/run/BuildInfo.hpp"

// Set by lib/io/run/CMakeLists.txt on this file only; the fallbacks serve a build without CMake.
#ifndef MFWAVE_VERSION
#define MFWAVE_VERSION "unknown"
#endif
#ifndef MFWAVE_GIT_REVISION
#define MFWAVE_GIT_REVISION "unknown"
#endif
#ifndef MFWAVE_SOURCE_DIR
#define MFWAVE_SOURCE_DIR ""
#endif
#ifndef MFWAVE_BINARY_DIR
#define MFWAVE_BINARY_DIR ""
#endif

namespace mfwave {

std::string mfwaveVersion() { return MFWAVE_VERSION; }
std::string mfwaveGitRevision() { return MFWAVE_GIT_REVISION; }
std::string mfwaveSourceFolder() { return MFWAVE_SOURCE_DIR; }
std::string mfwaveBuildFolder() { return MFWAVE_BINARY_DIR; }

}  // namespace mfwave
