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

// The catalogue's methods for which `supports` holds.
template <typename Predicate>
std::vector<std::string> methodsWhere(Predicate supports) {
  std::vector<std::string> names;
  for (const MethodEntry& m : methodCatalogue())
    if (supports(m.supports)) names.push_back(m.name);
  return names;
}

}  // namespace

std::string UnsupportedFeature::message() const {
  return method + " does not support " + feature + "; supported by: " +
         (supportedBy.empty() ? std::string("no method of the catalogue") : scene::joinNames(supportedBy));
}

std::vector<UnsupportedFeature> unsupportedFeatures(const Scene& scene, const MethodEntry& method) {
  std::vector<UnsupportedFeature> out;
  const MethodSupport& s = method.supports;
  const int d = scene.geometry.dimension;
  if (!contains(s.dimensions, d))
    out.push_back({"scene.dimension", std::to_string(d) + "-D scenes",
                   methodsWhere([d](const MethodSupport& m) { return contains(m.dimensions, d); }), ""});
  const std::string& shape = scene.geometry.shape;
  if (!contains(s.shapes, shape))
    out.push_back({"geometry.shape", "the shape '" + shape + "'",
                   methodsWhere([&shape](const MethodSupport& m) { return contains(m.shapes, shape); }), ""});
  for (std::size_t i = 0; i < scene.boundaries.size(); ++i) {
    const BoundaryType type = scene.boundaries[i].type;
    if (!contains(s.boundaries, type) && !standInFor(s, type))
      out.push_back({"boundary[" + std::to_string(i) + "].type", boundaryTypeName(type) + " boundaries",
                     methodsWhere([type](const MethodSupport& m) { return contains(m.boundaries, type); }), ""});
  }
  for (std::size_t i = 0; i < scene.loads.size(); ++i) {
    const LoadType type = scene.loads[i].type;
    if (!contains(s.loads, type))
      out.push_back({"load[" + std::to_string(i) + "].type", loadTypeName(type) + " loads",
                     methodsWhere([type](const MethodSupport& m) { return contains(m.loads, type); }), ""});
  }
  const std::string& integrator = scene.integrator.name;
  if (!contains(s.integrators, integrator))
    out.push_back({"integrator.name", "the integrator '" + integrator + "'",
                   methodsWhere([&integrator](const MethodSupport& m) { return contains(m.integrators, integrator); }),
                   ""});
  for (UnsupportedFeature& f : out) f.method = method.name;
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
