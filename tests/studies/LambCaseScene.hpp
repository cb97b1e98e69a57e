#pragma once
// The lamb2d and lamb3d scenes (data/scenes/lamb2d.toml, lamb3d.toml) read as the Lamb case tests
// need them, without the driver: the very weak SPH's [method] keys and the study keys the scenes set
// registered, so that every method's case (RK collocation, the UL-SPH, spectral elements) runs the
// shipped scene.

#include "io/scene/LoadScene.hpp"
#include "studies/lamb3d/LambCase.hpp"
#include "wiring/VeryWeakSphSpec.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace mfwave::lamb3d::testing {

// `sceneFile` a file of data/scenes ("lamb2d.toml", "lamb3d.toml").
inline StudySettings lambCaseStudy(const std::string& sceneFile, const std::vector<std::string>& overrides,
                                   Real errorWindow = 6.0) {
  SceneSchema schema = SceneSchema::common();
  addVeryWeakSphKeys(schema);
  schema.add("study", ValueType::Table);
  for (const char* key : {"study.spacings", "study.free_block_lower", "study.free_block_upper"})
    schema.add(key, ValueType::NumberArray);
  for (const char* key : {"study.error_window", "study.published_smoothing_rate", "study.strong_smoothing_rate"})
    schema.add(key, ValueType::Number);
  schema.add("study.compare_published", ValueType::Boolean);
  SceneReader reader = loadScene(std::string(SCENES_FOLDER) + "/" + sceneFile, overrides, schema);
  StudySettings study;
  study.scene = readScene(reader);
  study.errorWindow = errorWindow;
  return study;
}

inline StudySettings lamb2dCaseStudy(const std::vector<std::string>& overrides, Real errorWindow = 6.0) {
  return lambCaseStudy("lamb2d.toml", overrides, errorWindow);
}

inline StudySettings lamb3dCaseStudy(const std::vector<std::string>& overrides, Real errorWindow = 6.0) {
  return lambCaseStudy("lamb3d.toml", overrides, errorWindow);
}

// Whether one of a case's notes contains `text`.
inline bool anyNoteHas(const std::vector<std::string>& notes, const std::string& text) {
  for (const std::string& n : notes)
    if (n.find(text) != std::string::npos) return true;
  return false;
}

// Every probe of a case whose method reports its state as it is (RK collocation's u^h, the UL-SPH,
// the spectral elements) has an exact response, and its raw and reported errors are the same.
inline void expectEveryProbeScoredAsRaw(const CaseResult& r) {
  for (const ProbeResult& p : r.probes) {
    EXPECT_TRUE(p.hasExact) << p.name;
    EXPECT_EQ(p.raw.relativeL2, p.reported.relativeL2) << p.name;
  }
}

}  // namespace mfwave::lamb3d::testing
