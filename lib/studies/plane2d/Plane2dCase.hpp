#pragma once
// One case of the plane2d study: plane strain on a square by RK collocation against the
// manufactured solution u_1 = u_2 = sin(pi x) sin(pi y) cos(w t) (zero displacement on every side)
// with the body force f = rho u_tt - L u it needs; the step checked against the integrator's limit
// on the assembled operator; and, before any case, the exact interior spectrum that refuses
// growing modes.

#include "io/run/StudyCases.hpp"
#include "io/scene/Scene.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace mfwave::plane2d {

struct CaseResult : StudyCase {
  int cells = 0;
  Real h = 0;
  Real errorU = 0, errorV = 0;
  Real orderU = std::nan(""), orderV = std::nan("");
};

// Runs one case with `cells` cells per side (RK order `order`, support a = ratio h; the manufactured
// solution at angular frequency w); appends its step-limit note (stability keys) to `notes`.
CaseResult runCase(const Scene& scene, int order, Real ratio, Real w, int cells, std::vector<std::string>& notes);

// Before any step: the exact spectrum of the interior rows on a periodic lattice
// (rkPlaneStrainGrowingModes, lib/wiring/CollocationSpec, which lamb2d's RK cases share; at h = 1:
// with a / h fixed the rows scale as 1 / h^2, so one spectrum serves every resolution). omega^2 < 0
// grows at every time step, whatever the integrator: RK collocation from a / h of about 2.8 on in
// 2-D, where the mass symbol changes sign (docs/studies/spectra.md). Refused with exit 3 unless
// stability.allow_growth, which runs on and says so in the summary (the returned notes).
std::vector<std::string> checkInteriorStability(const Scene& scene, int order, Real ratio);

}  // namespace mfwave::plane2d
