#pragma once
// The Lamb study's plan (lamb2d and lamb3d): its scene keys and the cases a scene asks for, read and
// checked before any case runs.
//
// The scene names its method by the catalogue's name (lib/catalogue); the study runs the catalogue's
// methods whose programs include it (very_weak_sph, reproducing_kernel, spectral_element,
// updated_lagrangian_sph), one plan reader each (LambPlan.cpp), and refuses any other with the list
// the catalogue gives. Each reader turns the scene into cases: the very weak SPH's variant at every
// spacing (with the published comparison, the strong filter and the free block where the scene asks),
// or one case per spacing of the other methods, the scene's spacing first (it writes exact.csv and
// the frames). Keys a method does not use but the scene sets (the very weak SPH's when another method
// runs a scene written for it) are read, still checked, and named in a note.

#include "studies/lamb3d/LambCase.hpp"

#include "io/scene/SceneReader.hpp"
#include "io/scene/SceneSchema.hpp"

#include <string>
#include <vector>

namespace mfwave::lamb3d {

struct Plan {
  StudySettings study;
  std::vector<CaseSettings> cases;
  std::vector<std::string> notes;  // for the summary: what the plan accepted and ignored
};

// "lamb2d" or "lamb3d".
const char* lambProgram(int dimension);

// The scene keys of the study in `dimension` (2 or 3): the common sections, the [method] keys of the
// methods it runs, and its [study] keys.
SceneSchema lambSchema(int dimension);

// The study settings and the cases of the scene in `reader` (read with lambSchema(D)); fails with the
// key for anything the study or the method cannot run, before any case runs.
template <int D>
Plan readLambPlan(SceneReader& reader);

// The catalogue's methods whose programs include the study in `dimension`.
std::vector<std::string> lambMethods(int dimension);

}  // namespace mfwave::lamb3d
