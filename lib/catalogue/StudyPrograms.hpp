#pragma once
// Which program runs a scene: `mfwave run` and `mfwave check` hand a scene to the study program (or
// analysis tool) that reads it, so that a run through `mfwave` gives everything that program gives
// (probes, frames, energy ledger, stability monitor, checkpoints, --set, --restart, summary.json,
// progress) and the study's figures stay the same.
//
// The program is found, in order: by the scene's [scene] name (a shipped study's scene or a copy of
// it: "lamb3d", "bar1d-sph", ...); by the file name of a shipped tool scene without a [scene]
// section ("spectra.toml", "planewave.toml", ...); by what the scene asks for (a finite-difference
// scene: wavefield; one surface_patch load on a half-space box by a method of the Lamb study:
// lamb2d / lamb3d). Anything else is refused, naming what each program runs.

#include <string>
#include <vector>

namespace mfwave {

struct StudyProgram {
  std::string program;                  // the executable's name
  std::string what;                     // one line: what it runs
  std::vector<std::string> sceneNames;  // [scene] name values it owns
  std::vector<std::string> sceneFiles;  // shipped scene files (data/scenes) it owns
  bool tool = false;                    // an analysis tool (no [scene] section, no time loop)
};

const std::vector<StudyProgram>& studyPrograms();

struct ProgramChoice {
  std::string program;
  std::string reason;  // "scene.name = \"lamb3d\"", "file planewave.toml", "method.name = finite_difference"
};

// What the scene at `scenePath` (with `--set` overrides) is run by. Throws InputError naming the key
// ("scene.name", "method.name" or "load") when no program runs it.
ProgramChoice programForScene(const std::string& scenePath, const std::vector<std::string>& overrides);

}  // namespace mfwave
