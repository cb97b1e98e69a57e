#pragma once
// One entry of the method catalogue: everything the rest of the code needs to know about a
// discretisation without knowing its kernel, written once (MethodCatalogue.cpp registers them).
//
//   name          the one name of the method in scenes (method.name), tools, the sweep and docs
//   variants      the values of its variant key (method.variant), if it has variants
//   supports      the scene features it can represent: dimensions, geometry shapes, boundary and
//                 load types, integrators. A scene that asks for anything else is refused before
//                 any work (SceneSupport.hpp), naming the key and the methods that do support it.
//   addOptions    registers its [method] keys (typed, with defaults and docs) in a schema
//   stepRule      how its stable step is found, in words (the step itself: integrators/TimeStep)
//   interiorRow   how the plan finds its stable step and dispersion: the lattice tools' interior
//                 row of the method (spectra/LatticeMethods) or a closed form
//   cost          measured memory per particle and rate, per dimension, for the plan's estimates
//   programs      the study programs that run it (mfwave run hands a scene to one of them)

#include "io/scene/BoundarySpec.hpp"
#include "io/scene/LoadSpec.hpp"
#include "io/scene/SceneSchema.hpp"

#include <array>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace mfwave {

struct MethodSupport {
  std::vector<int> dimensions;
  std::vector<std::string> shapes;  // geometry.shape: "line", "rectangle", "block"
  std::vector<BoundaryType> boundaries;
  std::vector<LoadType> loads;
  std::vector<std::string> integrators;  // integrator.name
  bool firstOrder = false;               // integrator.name takes the first-order names (UL-SPH)
  // Boundary types the method does not represent but runs with another in their place, as its study
  // does and says in a note (the Lamb study: RK collocation fixes the transmitting faces, the UL-SPH
  // leaves them free): {scene's type, the type that stands in}.
  std::vector<std::pair<BoundaryType, BoundaryType>> standIns = {};
  // Solids other than the box ([[shape]], geometry.solid, [[region]]: wiring/SolidScene): the
  // programs that run the method on them (empty: the method runs boxes only).
  std::vector<std::string> solidPrograms = {};
  // Materials by region ([[region]] with its own material) on those solids, interfaces honoured.
  bool materialRegions = false;
  // Cracks ([[crack]]) on those solids: the material's interactions cut across them.
  bool cracks = false;
  // Named surfaces of those solids held fixed ([[surface_boundary]], type fixed).
  bool fixedSurfaces = false;
};

// Measured cost of a whole run on one core, per dimension (index D - 1); 0 where not measured. The
// plan predicts peak memory = baseMiB + bytesPerParticle N + fillMiB (N / fillNodes)^fillExponent
// (a sparse LU's fill, growing faster than N) and wall time = setupSecondsPerParticle N + N steps /
// particleStepsPerSecond.
struct MethodCost {
  std::array<double, 3> baseMiB{};  // the process before any particle (libraries, the exact reference)
  std::array<double, 3> bytesPerParticle{};
  std::array<double, 3> particleStepsPerSecond{};
  std::array<double, 3> setupSecondsPerParticle{};
  std::array<double, 3> fillMiB{};
  double fillNodes = 1, fillExponent = 1;
  // A method whose work per particle grows with N (a sparse LU's fill: RK collocation): set-up per
  // particle and time per particle-step scale as (N / growthNodes)^(growthExponent - 1).
  std::array<double, 3> growthNodes{1, 1, 1};
  double growthExponent = 1;
  std::string measured;  // where the figures come from (scene, spacings, date)
  // On a scene's own solid (the program that runs the method on shapes assembles differently: the
  // cut-cell Galerkin's sparse matrices): per node inside the solid; 0 where not measured (the box
  // figures then serve).
  std::array<double, 3> solidBaseMiB{};
  std::array<double, 3> solidBytesPerParticle{};
  std::array<double, 3> solidParticleStepsPerSecond{};
  std::array<double, 3> solidSetupSecondsPerParticle{};
  std::string solidMeasured;
};

// How the plan reaches the method's spectrum.
enum class InteriorRow {
  Lattice,         // the lattice tools' interior row (latticeMethodStencil) of latticeName
  SpectralElement  // GLL elements: the central difference's own phase error and a closed-form step
};

struct MethodEntry {
  std::string name;
  std::string title;     // one line: "Very weak form SPH (Ding, Long, Wu)"
  std::string summary;   // a few lines for `mfwave methods`
  std::vector<std::string> variants;  // method.variant values, the default first (empty: none)
  MethodSupport supports;
  std::function<void(SceneSchema&)> addOptions;
  std::string stepRule;
  InteriorRow interiorRow = InteriorRow::Lattice;
  MethodCost cost;
  std::vector<std::string> programs;
};

}  // namespace mfwave
