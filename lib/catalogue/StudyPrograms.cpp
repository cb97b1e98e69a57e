#include "catalogue/StudyPrograms.hpp"

#include "catalogue/MethodCatalogue.hpp"
#include "core/Error.hpp"
#include "io/scene/LoadScene.hpp"

#include <filesystem>
#include <toml++/toml.h>

namespace mfwave {

const std::vector<StudyProgram>& studyPrograms() {
  static const std::vector<StudyProgram> programs = {
      {"lamb3d", "the 3-D Lamb problem: one surface_patch load on a block, every method of the Lamb study", {"lamb3d"},
       {"lamb3d.toml"}, false},
      {"lamb2d", "the plane-strain Lamb problem: one surface_patch load on a rectangle", {"lamb2d"}, {"lamb2d.toml"},
       false},
      {"solid",
       "a scene's own solid ([[shape]], geometry.solid, [[region]], [[crack]]) by the very weak SPH on cut cells, RK "
       "collocation, the UL- or TL-SPH",
       {"lamb2d_inclined", "lamb2d_halfplane", "layered_cavity"}, {}, false},
      {"wavefield", "any finite_difference scene: a scalar wave on a line, rectangle or block with point loads",
       {"block-ricker", "wavefield"}, {"block-ricker.toml"}, false},
      {"wave1d", "the 1-D standing wave and its step limits (finite differences)", {"wave1d"}, {"wave1d.toml"}, false},
      {"bar1d", "the Luo-Liu-Huang fixed-free bar by RK or RB collocation", {"bar1d"}, {"bar1d.toml"}, false},
      {"plane2d", "a plane-strain block by RK collocation", {"plane2d"}, {"plane2d.toml"}, false},
      {"bar1d-sph", "two bars meeting at +-v0 by the updated-Lagrangian SPH", {"bar1d-sph"}, {"bar1d-sph.toml"},
       false},
      {"plate", "the oscillating cantilever plate (UL-SPH, TL-SPH and very weak SPH cases)", {"plate"},
       {"plate.toml"}, false},
      {"rings", "two colliding rubber rings by the updated-Lagrangian SPH", {"rings"}, {"rings.toml"}, false},
      {"planewave", "a plane wave in a periodic box by a linear method's interior row", {}, {"planewave.toml"}, false},
      {"spectra", "FFT dispersion spectra of every lattice method", {}, {"spectra.toml"}, true},
      {"stability_atlas", "stable steps and growing modes of every method, kernel and support", {},
       {"stability-atlas.toml"}, true},
      {"dispersion", "RK and RB collocation dispersion (Luo-Liu-Huang Fig. 2)", {}, {"collocation-dispersion.toml"},
       true},
      {"stability", "RK and RB collocation critical steps (Luo-Liu-Huang bar)", {}, {"collocation-stability.toml"},
       true},
  };
  return programs;
}

namespace {

std::string listPrograms() {
  std::string out;
  for (const StudyProgram& p : studyPrograms()) out += "\n  " + p.program + ": " + p.what;
  return out;
}

}  // namespace

ProgramChoice programForScene(const std::string& scenePath, const std::vector<std::string>& overrides) {
  // The common schema is enough to apply the overrides and look at a few keys; the program that
  // runs the scene checks every key.
  const SceneReader reader = loadScene(scenePath, overrides);
  const toml::table& root = reader.root();
  const std::optional<std::string> name = root.at_path("scene.name").value<std::string>();
  if (name)
    for (const StudyProgram& p : studyPrograms())
      for (const std::string& n : p.sceneNames)
        if (n == *name) return {p.program, "scene.name = \"" + *name + "\""};
  const std::string file = std::filesystem::path(scenePath).filename().string();
  if (!root.contains("scene"))
    for (const StudyProgram& p : studyPrograms())
      for (const std::string& f : p.sceneFiles)
        if (f == file) return {p.program, "the shipped scene " + file};
  const std::string method = root.at_path("method.name").value<std::string>().value_or("");
  if (root.contains("shape") || root.contains("region") || root.contains("crack") || root.at_path("geometry.solid"))
    return {"solid", "the scene describes its solid ([[shape]], geometry.solid, [[region]] or [[crack]])"};
  const std::int64_t dimension = root.at_path("scene.dimension").value<std::int64_t>().value_or(0);
  if (method == "finite_difference") return {"wavefield", "method.name = finite_difference"};
  const toml::array* loads = root.at_path("load").as_array();
  const bool onePatch = loads && loads->size() == 1 && loads->front().as_table() &&
                        loads->front().as_table()->at_path("type").value<std::string>() == "surface_patch";
  // The Lamb study's methods are the catalogue's that name it among their programs.
  const MethodEntry* entry = findMethod(method);
  const bool lambMethod = entry && (runsIn(*entry, "lamb2d") || runsIn(*entry, "lamb3d"));
  if (lambMethod && onePatch && (dimension == 2 || dimension == 3))
    return {dimension == 3 ? "lamb3d" : "lamb2d",
            "method.name = " + method + " with one surface_patch load in " + std::to_string(dimension) + "-D"};
  if (!root.contains("scene"))
    throw InputError("scene", "the scene has no [scene] section and is not a shipped tool scene; the programs:" +
                                  listPrograms());
  if (!lambMethod && method != "finite_difference")
    throw InputError("method.name", "no program runs a scene of '" + method + "' outside its studies (scene.name = \"" +
                                        name.value_or("") + "\" names none of them); the programs:" + listPrograms());
  throw InputError("load", "a scene of " + method + " is run by the Lamb study, which takes exactly one surface_patch "
                           "load on a 2-D or 3-D box; the programs:" + listPrograms());
}

}  // namespace mfwave
