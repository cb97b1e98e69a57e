#pragma once
// The files mfwave ships beside its programs (data/scenes, data/reference, the plot scripts in
// analysis/), found alike by every program. A data folder holds data/ and analysis/ as the source
// tree does; the places, in the order they are tried:
//   1. $MFWAVE_DATA_DIR, when set (a copy of the data anywhere);
//   2. <the executable's folder>/../share/mfwave (an installed program: /usr/bin -> /usr/share/mfwave);
//   3. the source tree, when the program runs from inside its build folder.
// docs/install.md shows the installed tree.

#include <optional>
#include <string>
#include <vector>

namespace mfwave {

struct ShippedDataPlace {
  std::string folder;  // a data folder (may not exist)
  std::string origin;  // where the place comes from, for messages: "MFWAVE_DATA_DIR", ...
};

// This process's executable (/proc/self/exe), or "" where it cannot be read.
std::string thisExecutable();

// The places for a program at `executable` (this process's own, /proc/self/exe, by default).
std::vector<ShippedDataPlace> shippedDataPlaces(const std::string& executable = {});

// The first place's path of `relative` (e.g. "data/scenes/lamb3d.toml") that exists, or nothing.
std::optional<std::string> findShippedFile(const std::string& relative, const std::string& executable = {});

// Every place `relative` was looked for, one per line, for the message when none has it.
std::string describeShippedSearch(const std::string& relative, const std::string& executable = {});

// The plot script a program ships, analysis/plot_<program>.py ('-' as '_'), if any place has one.
std::optional<std::string> findPlotScript(const std::string& program);

// A data file a scene names (e.g. study.rk_reference = "data/reference/..."): `path` itself when it
// exists from the working folder, else, when relative, the first shipped place that has it; throws
// InputError(key, ...) naming every place looked otherwise.
std::string resolveDataFile(const std::string& path, const std::string& key);

}  // namespace mfwave
