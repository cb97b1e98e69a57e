#pragma once
// The lamb2d and lamb3d scenes (data/scenes/lamb2d.toml, lamb3d.toml) read as the Lamb case tests
// need them, without the driver: read with the study's own schema (lambSchema), so that every method's
// case (RK collocation, the UL-SPH, spectral elements) runs the shipped scene.

#include "io/scene/LoadScene.hpp"
#include "studies/lamb3d/LambCase.hpp"
#include "studies/lamb3d/LambPlan.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace mfwave::lamb3d::testing {

// `sceneFile` a file of data/scenes ("lamb2d.toml", "lamb3d.toml").
inline StudySettings lambCaseStudy(const std::string& sceneFile, const std::vector<std::string>& overrides,
                                   Real errorWindow = 6.0) {
  const SceneSchema schema = lambSchema(sceneFile == "lamb3d.toml" ? 3 : 2);  // the study's own keys
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
