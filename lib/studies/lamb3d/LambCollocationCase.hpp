#pragma once
// One RK collocation case of the lamb2d or lamb3d study: the plane-strain or 3-D Lamb problem of the
// scene by Luo-Liu-Huang's strong-form collocation with reproducing-kernel shape functions, on the
// same lattice nodes as the very weak SPH case at this spacing, scored against the same exact
// response. One implementation for D = 2 and 3.
//
//   nodes               the scene's rectangle or block lattice (buildParticles, physical particles
//                       only); collocation points = nodes (Nc = Ns)
//   interior rows       rho u'' - L u = 0 (Luo-Liu-Huang eq. (12))
//   traction rows       the loaded face's nodes on no other face (2-D: without its two corners,
//                       3-D: without its edges and corners): sigma(u) n = h(x, t) (eq. (13)), n the
//                       face's outward normal, h = traction w(x) f(t), w the product over the face's
//                       axes of 1 inside the patch, 1/2 on its edges (which fall on nodes: the
//                       trapezoid rule then gives the load's total force), 0 outside (3-D: 1/4 at
//                       the square's corners)
//   displacement rows   every other boundary node (sides, bottom, the loaded face's corners or
//                       edges): u = 0
//
// Fixed faces stand in for the scene's transmitting ones: the case notes when the first P wave
// they reflect reaches a probe. For data/scenes/lamb2d.toml 13.5 / sqrt 3 = 7.8 after the start,
// from the strip's edge via the +x face to the surface receiver, after the error window of 6; runs
// longer than that see the reflections the dashpots would have absorbed. For data/scenes/lamb3d.toml
// (a 7-wide block) 4.5 / sqrt 3 = 2.6, from the square's edge via the +x face to the surface
// receiver, INSIDE the window (the centre sees the side faces' at 6.5 / sqrt 3 = 3.75, the buried
// probe at 6.58 / sqrt 3 = 3.80): the 3-D errors include these reflections (measured below).
//
// The system is ConstrainedCollocationSystem (the boundary rows imposed at every instant, U the
// values at the interior nodes), stepped by makeConstrainedIntegrator at the scene's fraction of
// the stable step 2 / omega_max (omega_max^2 by power iteration on the assembled operator). The
// probes read the interpolated field u^h(x_p) = sum_J psi_J(x_p) d_J (velocity: d'), so a probe on
// the loaded face sees the traction rows' solution. The energy ledger and frames of the very weak
// SPH case are not made (the case notes it); StabilityMonitor stops a run that blows up (exit 3).
//
// What the traction rows do, measured on data/scenes/lamb2d.toml (m = 2, a / h = 2.5, central
// difference at half the stable step):
//  - Stability. K = (1/rho) A_I C^{-1} [I; 0] (G-bar of Luo-Liu-Huang eq. (37)) is not symmetric.
//    With displacement rows on every face its spectrum is real and positive (dx = 0.5: all 930
//    eigenvalues); with the free face's traction rows some nearly coincident pairs of modes turn
//    into complex pairs, |Im lambda| / Re lambda ~ 3e-3, which grow like exp(Re sqrt(-lambda) t):
//    dx = 0.5: 112 of 930 eigenvalues, fastest 0.0134 / s (lambda = 74.6 +- 0.23i, a mode over the
//    whole rectangle, largest at (-4.5, -2)); dx = 0.25: 522 of 3906, 0.0138 / s. The rate does not
//    fall with h: the same problem on an 8 x 4 rectangle, exactly similar to the 16 x 8 one at twice
//    the spacing (its eigenvalues 4 times, its rates twice those), grows at 0.031 / s at dx = 0.5
//    (measured), 0.027 at 0.25 and 0.028 at 0.125 (from the 16 x 8 spectra). Every support with a
//    stable interior has such pairs (a / h = 2.2: 0.041 / s, 2.7: 0.022 / s at dx = 0.5). The growth
//    is the semi-discrete system's, in time and not per step (no integrator or step holds it):
//    runs to t = 1500 stop (exit 3, "growth after the loads ended") at t = 1210 (dx = 0.5), 1260
//    (dx = 0.5, half the step), 1415 (dx = 0.5, Newmark) and 1315 (dx = 0.25), the first at node
//    (-4.5, -2). Over the error window the pairs gain at most exp(0.0138 * 6) = 1.09 and the
//    errors do not see them. The largest eigenvalues are real and clustered (760.71, 760.40,
//    760.36 at dx = 0.25), so the power iteration creeps up to omega_max^2: after 400 iterations
//    0.08 % under it, i.e. a step 0.04 % above the true limit, well inside integrator.cfl = 0.5.
//  - Accuracy. A traction row slaves its node to the interior ones (sigma(u^h) n = h holds at the
//    node, which has no mass), so a jump in the load's rate shows at once in the surface velocity,
//    by O(h): about 0.05 per unit of rate at dx = 0.25, half that at 0.125 (the first sample, where
//    the rate is taken as 1/2, moves at 0.026 and 0.013 where the exact response starts from 0),
//    and the centre's velocity drops by about 0.1 when the rate turns from 1 to -1 at t = 1. The
//    surface receiver 2 away sees the Rayleigh pulse early (arrival -0.11 s at dx = 0.25, -0.044 s
//    at 0.0625). The errors converge at about first order at the surface: centre 0.147, 0.054,
//    0.021; receiver 0.343, 0.158, 0.077; buried 0.123, 0.054, 0.026 at dx = 0.25, 0.125, 0.0625
//    (the Galerkin very weak SPH: 0.079, 0.032, 0.012; 0.103, 0.061, 0.028; 0.102, 0.048, 0.021).
//    The strip's edges are no worse than its centre: a probe at the edge (x = 0.5) errs 0.107 and
//    0.040 (dx = 0.25, 0.125), one at x = 0.25 0.134 and 0.051; away from the strip the error grows
//    with distance along the surface (x = 1: 0.238, 0.101).

#include "studies/lamb3d/LambCase.hpp"

#include <string>

namespace mfwave::lamb3d {

// Runs the collocation case `settings` (settings.collocation set) of a 2-D scene with one
// surface_patch load on a free face. Throws InputError("method.name") for another dimension,
// InputError("load") without such a load, InputError on the step limit (checkStepLimit) and
// InstabilityError (naming the node and its position) when the run blows up.
CaseResult runCollocationCase(const StudySettings& study, const CaseSettings& settings, const std::string& folder,
                              bool progress);

}  // namespace mfwave::lamb3d
