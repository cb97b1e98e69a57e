// mfwave: one program for every scene.
//
//   mfwave methods [--json]                     the method catalogue: what each method supports, its options
//   mfwave check SCENE [--set k=v ...]          validate the scene and print the resolved model, run nothing
//   mfwave plan  SCENE [--set k=v ...] [--spacing DX] [--target E] [--json]
//                                               predict particles, memory, step, wall time and phase error
//   mfwave run   SCENE [--set k=v ...] [--out DIR] [--restart DIR] [--checkpoint-every N|Ts] [--quiet] [--threads N]
//                                               run the scene by the program that reads it (StudyPrograms.hpp)
//
// check and plan read the scene through the catalogue (lib/catalogue): the method it names, and
// what that method cannot represent refused by name. run and check then hand the scene to its study
// program (with --check for check), which reads and checks every key of its own and gives the run
// everything a study driver gives (probes, frames, energy ledger, stability monitor, checkpoints,
// summary.json, progress); the program is looked for beside this one.

#include "catalogue/CatalogueScene.hpp"
#include "catalogue/MethodCatalogue.hpp"
#include "catalogue/PlanReport.hpp"
#include "catalogue/StudyPrograms.hpp"
#include "io/run/DriverCommandLine.hpp"
#include "io/run/RunSummary.hpp"
#include "io/run/RunDriver.hpp"
#include "io/run/ShippedData.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iomanip>
#include <sstream>
#include <iostream>
#include <unistd.h>

using namespace mfwave;

namespace {

namespace fs = std::filesystem;

// The program `name` beside this one: installed, every program is in bin/; in the build tree the
// study drivers are in drivers/ and the analysis tools in analysis/.
std::string programPath(const std::string& name) {
  const std::string self = thisExecutable();
  const fs::path here = self.empty() ? fs::path(".") : fs::path(self).parent_path();
  for (const fs::path& candidate : {here / name, here.parent_path() / "analysis" / name,
                                    here.parent_path() / "drivers" / name})
    if (fs::exists(candidate)) return candidate.string();
  throw Error("the program '" + name + "' that runs this scene is not beside mfwave (looked in " + here.string() +
              " and its ../analysis, ../drivers)");
}

// Replaces this process by `program` with `arguments`; returns only on failure.
int execute(const std::string& program, const std::vector<std::string>& arguments) {
  std::vector<char*> argv;
  std::vector<std::string> storage = arguments;
  storage.insert(storage.begin(), program);
  for (std::string& a : storage) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::cout.flush();
  execv(program.c_str(), argv.data());
  std::cerr << "mfwave: error: cannot start " << program << '\n';
  return 1;
}

// The scene a run or check names: SCENE, or with --restart and no SCENE the restarted folder's
// scene.resolved.toml (for choosing the program; the program itself reads it again).
std::string sceneForDispatch(const std::string& scene, const std::string& restart) {
  if (!scene.empty()) return scene;
  if (!restart.empty()) return (fs::path(restart) / "scene.resolved.toml").string();
  throw InputError("SCENE", "give a scene file (or --restart DIR)");
}

struct SceneArguments {
  std::string scene;
  std::vector<std::string> overrides;
};

void addSceneArguments(CLI::App& command, SceneArguments& a, bool required) {
  auto* scene = command.add_option("SCENE", a.scene, "scene file (TOML; docs/scenes.md)");
  if (required) scene->required();
  scene->check(CLI::ExistingFile);
  command.add_option("--set", a.overrides, "override a scene key, e.g. --set geometry.spacing=0.25 (repeatable)")
      ->allow_extra_args(false)
      ->take_all();
}

std::vector<std::string> withOverrides(std::vector<std::string> arguments, const std::vector<std::string>& overrides) {
  for (const std::string& o : overrides) {
    arguments.push_back("--set");
    arguments.push_back(o);
  }
  return arguments;
}

int methods(bool json) {
  if (json) std::cout << catalogueJson().dump(2) << '\n';
  else printCatalogue(std::cout);
  return 0;
}

int check(const SceneArguments& a) {
  const ProgramChoice program = programForScene(a.scene, a.overrides);
  if (const std::optional<CatalogueScene> read = readCatalogueScene(a.scene, a.overrides)) {
    const Prediction p = predictScene(read->scene, read->choice);
    printResolvedModel(std::cout, read->scene, read->choice, p);
    for (const std::string& note : read->notes) std::cout << "note         " << note << '\n';
  }
  std::cout << "program      " << program.program << " (" << program.reason << ")\n";
  return execute(programPath(program.program), withOverrides({"--scene", a.scene, "--check"}, a.overrides));
}

int plan(const SceneArguments& a, Real spacing, Real target, bool json) {
  const std::optional<CatalogueScene> read = readCatalogueScene(a.scene, a.overrides);
  if (!read) {
    const ProgramChoice program = programForScene(a.scene, a.overrides);
    if (json)
      std::cout << nlohmann::json{{"program", program.program}, {"particles", nullptr}, {"memory_bytes", nullptr},
                                  {"stable_step", nullptr}, {"steps", nullptr}, {"wall_seconds", nullptr},
                                  {"phase_error", nullptr},
                                  {"notes", {"an analysis tool's scene: no particles stepped, nothing to plan"}}}
                       .dump(2)
                << '\n';
    else
      std::cout << a.scene << " is an analysis tool's scene (" << program.program
                << "): no particles are stepped, nothing to plan\n";
    return 0;
  }
  Prediction p = predictScene(read->scene, read->choice, spacing);
  p.notes.insert(p.notes.begin(), read->notes.begin(), read->notes.end());
  const double machine = physicalMemoryMiB();
  if (p.memoryBytes / 1048576.0 > machine) {
    std::ostringstream note;
    note << std::setprecision(3) << "needs about " << p.memoryBytes / 1073741824.0 << " GiB, more than this machine's "
         << machine / 1024.0 << " GiB: the run would be refused (a coarser spacing, or the ranks: docs/scaling.md)";
    p.notes.insert(p.notes.begin(), note.str());
  }
  nlohmann::json out = predictionJson(p);
  if (!json) printPrediction(std::cout, p);
  if (target > 0) {
    const TargetAnswer answer = cheapestForTarget(read->scene, target, physicalMemoryMiB() * 1048576.0);
    if (json) {
      out["target"] = target;
      out["cheapest"] = answer.found ? predictionJson(answer.best) : nlohmann::json(nullptr);
    } else if (answer.found) {
      std::cout << "\ncheapest for a phase error <= " << target << ": " << answer.best.method << " at spacing "
                << answer.best.spacing << " m (" << answer.best.particles << " particles, phase error "
                << answer.best.phaseError << ", about " << answer.best.wallSeconds << " s, "
                << answer.best.memoryBytes / 1048576.0 << " MiB)\n"
                << "  mfwave run " << a.scene << " --set method.name=" << answer.best.method.substr(0, answer.best.method.find(' '))
                << " --set geometry.spacing=" << answer.best.spacing << '\n';
    } else {
      std::cout << "\nno method and spacing of the catalogue reaches a phase error <= " << target
                << " within this machine's memory\n";
    }
  }
  if (json) std::cout << out.dump(2) << '\n';
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("mfwave: run, check and plan any scene by any method of the catalogue", "mfwave");
  app.require_subcommand(1);
  app.set_version_flag("--version", versionString("mfwave"));

  bool methodsJson = false;
  CLI::App* methodsCommand = app.add_subcommand("methods", "list the method catalogue: what each supports, its options");
  methodsCommand->add_flag("--json", methodsJson, "one JSON array");

  SceneArguments checkArgs;
  CLI::App* checkCommand =
      app.add_subcommand("check", "validate the scene and print the resolved model; nothing is run or written");
  addSceneArguments(*checkCommand, checkArgs, true);

  SceneArguments planArgs;
  Real planSpacing = 0, planTarget = 0;
  bool planJson = false;
  CLI::App* planCommand = app.add_subcommand(
      "plan", "predict particles, peak memory, stable step, steps, wall time and phase error before any stepping");
  addSceneArguments(*planCommand, planArgs, true);
  planCommand->add_option("--spacing", planSpacing, "plan at this lattice spacing instead of the scene's")
      ->check(CLI::PositiveNumber);
  planCommand->add_option("--target", planTarget, "also name the cheapest method and spacing for this phase error")
      ->check(CLI::PositiveNumber);
  planCommand->add_flag("--json", planJson, "one JSON object");

  SceneArguments runArgs;
  std::string out, restart, checkpointEvery;
  int threads = -1;
  bool quiet = false;
  CLI::App* runCommand =
      app.add_subcommand("run", "run the scene by its method, through the study program that reads it");
  addSceneArguments(*runCommand, runArgs, false);
  runCommand->add_option("--out", out, "output folder (default: the scene's output.folder)");
  runCommand->add_option("--restart", restart, "go on from the newest checkpoint in this output folder")
      ->check(CLI::ExistingDirectory);
  runCommand->add_option("--checkpoint-every", checkpointEvery, "a checkpoint every N steps or T seconds (600s)");
  runCommand->add_option("--threads", threads, "OpenMP threads")->check(CLI::NonNegativeNumber);
  runCommand->add_flag("--quiet", quiet, "no progress display");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version: 0; a usage error: 2, as every driver says bad input.
    return app.exit(e) == 0 ? 0 : 2;
  }

  return runDriver("mfwave", [&]() -> int {
    if (methodsCommand->parsed()) return methods(methodsJson);
    if (checkCommand->parsed()) return check(checkArgs);
    if (planCommand->parsed()) return plan(planArgs, planSpacing, planTarget, planJson);
    const ProgramChoice program = programForScene(sceneForDispatch(runArgs.scene, restart), runArgs.overrides);
    std::vector<std::string> arguments;
    if (!runArgs.scene.empty()) arguments = {"--scene", runArgs.scene};
    arguments = withOverrides(arguments, runArgs.overrides);
    if (!out.empty()) arguments.insert(arguments.end(), {"--out", out});
    if (!restart.empty()) arguments.insert(arguments.end(), {"--restart", restart});
    if (!checkpointEvery.empty()) arguments.insert(arguments.end(), {"--checkpoint-every", checkpointEvery});
    if (threads >= 0) arguments.insert(arguments.end(), {"--threads", std::to_string(threads)});
    if (quiet) arguments.push_back("--quiet");
    if (!quiet) std::cout << "mfwave run: " << program.program << " (" << program.reason << ")\n";
    return execute(programPath(program.program), arguments);
  });
}
