#include "catalogue/SceneSupport.hpp"

#include "catalogue/MethodCatalogue.hpp"
#include "core/Error.hpp"
#include "io/scene/Format.hpp"

#include <algorithm>

namespace mfwave {
namespace {

const BoundaryType* standInFor(const MethodSupport& s, BoundaryType type) {
  for (const auto& [asked, used] : s.standIns)
    if (asked == type) return &used;
  return nullptr;
}

template <typename T>
bool contains(const std::vector<T>& list, const T& value) {
  return std::find(list.begin(), list.end(), value) != list.end();
}

// Adds the feature `value` of the scene at `key` to `out` unless `method` lists it in its `field`
// (or, for a boundary, has a stand-in for it), with the catalogue's methods that do list it.
template <typename T>
void requireSupport(std::vector<UnsupportedFeature>& out, const MethodEntry& method,
                    std::vector<T> MethodSupport::*field, const T& value, std::string key, std::string feature,
                    bool standIn = false) {
  if (contains(method.supports.*field, value) || standIn) return;
  std::vector<std::string> supportedBy;
  for (const MethodEntry& m : methodCatalogue())
    if (contains(m.supports.*field, value)) supportedBy.push_back(m.name);
  out.push_back({std::move(key), std::move(feature), supportedBy, method.name});
}

}  // namespace

std::string UnsupportedFeature::message() const {
  return method + " does not support " + feature + "; supported by: " +
         (supportedBy.empty() ? std::string("no method of the catalogue") : scene::joinNames(supportedBy));
}

std::vector<UnsupportedFeature> unsupportedFeatures(const Scene& scene, const MethodEntry& method) {
  std::vector<UnsupportedFeature> out;
  const int d = scene.geometry.dimension;
  requireSupport(out, method, &MethodSupport::dimensions, d, "scene.dimension", std::to_string(d) + "-D scenes");
  requireSupport(out, method, &MethodSupport::shapes, scene.geometry.shape, "geometry.shape",
                 "the shape '" + scene.geometry.shape + "'");
  for (std::size_t i = 0; i < scene.boundaries.size(); ++i) {
    const BoundaryType type = scene.boundaries[i].type;
    requireSupport(out, method, &MethodSupport::boundaries, type, "boundary[" + std::to_string(i) + "].type",
                   boundaryTypeName(type) + " boundaries", standInFor(method.supports, type) != nullptr);
  }
  for (std::size_t i = 0; i < scene.loads.size(); ++i)
    requireSupport(out, method, &MethodSupport::loads, scene.loads[i].type, "load[" + std::to_string(i) + "].type",
                   loadTypeName(scene.loads[i].type) + " loads");
  requireSupport(out, method, &MethodSupport::integrators, scene.integrator.name, "integrator.name",
                 "the integrator '" + scene.integrator.name + "'");
  return out;
}

std::vector<UnsupportedFeature> unsupportedSolidFeatures(const MethodEntry& method, const SolidFeatures& asked) {
  std::vector<UnsupportedFeature> out;
  const auto require = [&](bool wanted, bool MethodSupport::*field, const char* key, const char* feature) {
    if (!wanted || method.supports.*field) return;
    std::vector<std::string> supportedBy;
    for (const MethodEntry& m : methodCatalogue())
      if (m.supports.*field) supportedBy.push_back(m.name);
    out.push_back({key, feature, supportedBy, method.name});
  };
  require(asked.regions, &MethodSupport::materialRegions, "region", "materials by region");
  require(asked.cracks, &MethodSupport::cracks, "crack", "cracks");
  require(asked.fixedSurfaces, &MethodSupport::fixedSurfaces, "surface_boundary", "fixed surfaces of a solid");
  return out;
}

std::vector<std::string> standInNotes(const Scene& scene, const MethodEntry& method) {
  std::vector<std::string> notes;
  for (std::size_t i = 0; i < scene.boundaries.size(); ++i) {
    const BoundaryType type = scene.boundaries[i].type;
    if (contains(method.supports.boundaries, type)) continue;
    if (const BoundaryType* used = standInFor(method.supports, type))
      notes.push_back("boundary[" + std::to_string(i) + "]: " + boundaryTypeName(type) + " faces run " +
                      boundaryTypeName(*used) + " by " + method.name + " (it has no " + boundaryTypeName(type) +
                      " boundary; reflections return from them)");
  }
  return notes;
}

void refuseUnsupported(const Scene& scene, const MethodEntry& method) {
  const std::vector<UnsupportedFeature> problems = unsupportedFeatures(scene, method);
  if (!problems.empty()) throw InputError(problems.front().key, problems.front().message());
}

}  // namespace mfwave
