#include "catalogue/CatalogueScene.hpp"

#include "catalogue/MethodCatalogue.hpp"
#include "catalogue/SceneSupport.hpp"
#include "integrators/IntegratorFactory.hpp"
#include "io/scene/Format.hpp"
#include "io/scene/LoadScene.hpp"
#include "io/scene/SceneError.hpp"
#include "wiring/SolidScene.hpp"
#include "wiring/UpdatedLagrangianSphSpec.hpp"

#include <toml++/toml.h>

#include <algorithm>

namespace mfwave {

std::optional<CatalogueScene> readCatalogueScene(const std::string& path, const std::vector<std::string>& overrides) {
  const SceneReader first = loadScene(path, overrides);
  if (!first.root().contains("scene")) return std::nullopt;
  const std::optional<std::string> name = first.root().at_path("method.name").value<std::string>();
  if (!name) throw first.error("method.name", "is required: one of the catalogue's methods (mfwave methods)");
  const MethodEntry* entry = findMethod(*name);
  if (!entry) {
    try {
      methodNamed(*name);
    } catch (const InputError& e) {
      throw first.error("method.name", scene::problemOf(e));
    }
  }
  CatalogueScene out;
  std::vector<std::string> sets = overrides;
  const std::string integrator = first.root().at_path("integrator.name").value<std::string>().value_or("");
  const std::vector<std::string> secondOrder = secondOrderIntegratorNames();
  const bool asTheLambStudy = entry->supports.firstOrder && integrator != "leapfrog" &&
                             std::find(secondOrder.begin(), secondOrder.end(), integrator) != secondOrder.end();
  if (asTheLambStudy) {
    // A scene written for a second-order method and run by the UL-SPH: the Lamb study steps it by
    // leapfrog at the method's own criteria (cfl 1) with its linear defaults (alpha 1, corrected
    // gradients; LambSolidSpec::linearDefaults), or the method's own keys where the scene sets them.
    sets.push_back("integrator.name=leapfrog");
    sets.push_back("integrator.cfl=1.0");
    out.notes.push_back("integrator.name = " + integrator + " is a second-order integrator: " + entry->name +
                        " is a first-order system, planned as the Lamb study runs it (leapfrog at its own step "
                        "criteria, Monaghan alpha 1, corrected kernel gradients, unless the scene's "
                        "method.viscosity_alpha / method.kernel_gradient_correction say otherwise)");
  }
  // A solid other than the box ([[shape]], [[region]], [[crack]], geometry.solid): only the methods that model
  // one (MethodSupport::solidPrograms); the scene is then read with the solid's keys, and the plan
  // counts the lattice nodes inside the solid.
  const toml::table& firstRoot = first.root();
  const char* solidKey = firstRoot.contains("shape")            ? "shape"
                         : firstRoot.contains("region")         ? "region"
                         : firstRoot.contains("crack")          ? "crack"
                         : firstRoot.at_path("geometry.solid") ? "geometry.solid"
                                                               : nullptr;
  if (solidKey && entry->supports.solidPrograms.empty()) {
    std::string by;
    for (const MethodEntry& m : methodCatalogue())
      if (!m.supports.solidPrograms.empty()) by += (by.empty() ? "" : ", ") + m.name;
    throw first.error(solidKey, entry->name + " does not support solids other than the box; supported by: " + by);
  }
  SceneSchema schema = catalogueSchema(*entry);
  if (solidKey) addSolidKeys(schema);
  SceneReader reader = loadScene(path, sets, schema);
  out.scene = readScene(reader);
  out.choice = readMethodChoice(reader, *entry, out.scene.geometry.dimension);
  if (solidKey)
    out.choice.solidFraction = out.scene.geometry.dimension == 3 ? readSceneSolid<3>(reader, out.scene).latticeFraction
                                                                 : readSceneSolid<2>(reader, out.scene).latticeFraction;
  if (asTheLambStudy) {
    // What the scene itself sets (the first reader's table holds no defaults filled in).
    const toml::table& root = first.root();
    // The Lamb study's UL-SPH keeps the method's defaults for what it does not set (its kernel and
    // h / dx): the scene's kernel keys are the very weak SPH's.
    const UpdatedLagrangianSphOptions method;
    const UpdatedLagrangianSphKeyDefaults study = smallAmplitudeWaveDefaults();
    out.choice.kernel = method.kernel;
    out.choice.smoothingLengthRatio = method.smoothingLengthRatio;
    out.choice.viscosityAlpha = root.at_path("method.viscosity_alpha").value<double>().value_or(study.viscosityAlpha);
    out.choice.gradientCorrection =
        root.at_path("method.kernel_gradient_correction").value<bool>().value_or(study.kernelGradientCorrection);
  }
  const std::vector<UnsupportedFeature> problems = unsupportedFeatures(out.scene, *entry);
  if (!problems.empty()) throw reader.error(problems.front().key, problems.front().message());
  for (const std::string& note : standInNotes(out.scene, *entry)) out.notes.push_back(note);
  return out;
}

}  // namespace mfwave
