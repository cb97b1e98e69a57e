#pragma once
// What build a result comes from: the release and the git revision (`git describe --always --dirty`
// at configure time, "unknown" outside a git checkout), printed by --version and kept in summary.json.

#include <string>

namespace mfwave {

std::string mfwaveVersion();
std::string mfwaveGitRevision();

// Where the build tree keeps its source: a program that runs from its build folder finds the
// shipped scenes there (io/run/ShippedData).
std::string mfwaveSourceFolder();
std::string mfwaveBuildFolder();

}  // namespace mfwave
