#pragma once
// The stability atlas's irregular clouds (docs/studies/stability-atlas.md, "Irregular clouds"):
// the [jitter] block of its scene and the jitter.csv it writes, from lib/spectra/JitteredCloud.

#include "spectra/LatticeMethods.hpp"
#include "io/scene/SceneReader.hpp"
#include "io/scene/SceneSchema.hpp"

#include <ostream>
#include <string>
#include <vector>

namespace mfwave {

struct JitterAtlasSettings {
  bool enabled = true;
  std::vector<std::string> methods;
  std::vector<int> dimensions, ulsphDimensions;
  std::vector<Real> jitters;
  int seeds = 3;
  long confirmSteps = 2000;
  int cells[4] = {0, 32, 12, 6};
  std::vector<Real> smoothingRatios, rkSupports;  // the supports (kernel and RK order: the atlas defaults)
};

struct JitterAtlasCounts {
  long points = 0, growing = 0, failed = 0, confirmed = 0, contradicted = 0;
};

void addJitterAtlasKeys(SceneSchema& schema);
JitterAtlasSettings readJitterAtlasSettings(SceneReader& reader);

// Writes the CSV header and one row per method, dimension, support, jitter and seed; prints a line
// per method and dimension. `defaults` carries the material, the kernel and the RK order.
JitterAtlasCounts writeJitterAtlas(const JitterAtlasSettings& settings, const LatticeMethodSettings& defaults,
                                   std::ostream& csv);

}  // namespace mfwave
