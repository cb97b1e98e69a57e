#pragma once
// Whether a method can represent what a scene asks for, decided from the catalogue before any
// work: the dimension, the geometry's shape, every boundary type, every load type and the
// integrator. A scene that asks a method for something it does not support is refused with an
// InputError naming the scene key (scene.dimension, geometry.shape, boundary[2].type,
// load[0].type, integrator.name) and the methods that do support it.

#include "catalogue/MethodEntry.hpp"
#include "io/scene/Scene.hpp"

#include <string>
#include <vector>

namespace mfwave {

struct UnsupportedFeature {
  std::string key;      // the scene key, e.g. "load[0].type"
  std::string feature;  // what it asks for, e.g. "point_force loads"
  std::vector<std::string> supportedBy;  // the catalogue's methods that support it
  std::string method;                    // the method that does not
  std::string message() const;           // "<method> does not support point_force loads; supported by: ..."
};

// Every feature of `scene` that `method` does not support (empty: it can run the scene).
std::vector<UnsupportedFeature> unsupportedFeatures(const Scene& scene, const MethodEntry& method);

// What a scene's own solid asks beyond its shapes.
struct SolidFeatures {
  bool regions = false;        // [[region]] with materials
  bool cracks = false;         // [[crack]]
  bool fixedSurfaces = false;  // [[surface_boundary]] of type fixed
};

// What of them `method` cannot represent: materials by region (key "region",
// MethodSupport::materialRegions), cracks ("crack", MethodSupport::cracks), fixed surfaces
// ("surface_boundary", MethodSupport::fixedSurfaces).
std::vector<UnsupportedFeature> unsupportedSolidFeatures(const MethodEntry& method, const SolidFeatures& asked);

// What the method runs in place of what the scene asks, where it has a stand-in (MethodSupport::standIns):
// one note per boundary entry, e.g. "boundary[0]: transmitting faces run fixed by reproducing_kernel
// (it has no transmitting boundary; reflections return from them)".
std::vector<std::string> standInNotes(const Scene& scene, const MethodEntry& method);

// Throws InputError(key, message) for the first unsupported feature.
void refuseUnsupported(const Scene& scene, const MethodEntry& method);

}  // namespace mfwave
