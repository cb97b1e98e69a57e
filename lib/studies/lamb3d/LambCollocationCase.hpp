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
// probe at 6.58 / sqrt 3 = 3.80): the 3-D errors include these reflections. Measured at dx = 0.5 on
// the scene's 13 x 13 x 7 free-block box with the same fixed faces (first reflection at 6.06):
// 0.278 / 0.387 / 0.361 against 0.281 / 0.505 / 0.368 (centre / receiver / buried), so they cost the
// surface receiver 0.12 and the other two under 0.01.
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
//
// In 3-D, measured on data/scenes/lamb3d.toml (m = 2, a / h = 2.2, the widest support whose
// interior rows do not grow; central difference at half the stable step):
//  - Stability. The traction rows' complex pairs grow far faster than in 2-D: at dx = 0.5 the
//    probes' envelope grows at 0.58 / s (e-folding 1.7 s, a period of about 0.7 s; 0.57 / s at
//    half the step, so the semi-discrete system's), and a run to t = 300 is stopped (exit 3,
//    "growth after the loads ended") at t = 34.6, at the interior node (0, 0, -0.5) under the load
//    centre (t = 35.2 at half the step). Extrapolated back along that rate the pair starts at about
//    1e-5 of the response, about 5e-4 of the centre's peak at t = 6: the errors over the window do
//    not see it. The rate was read off the probes, not off the operator's spectrum (a dense
//    non-symmetric 6591 x 6591 eigenproblem at dx = 0.5, not attempted).
//  - Accuracy. Centre / receiver / buried 0.281 / 0.505 / 0.368 at dx = 0.5, 0.144 / 0.430 / 0.157
//    at 0.25 (the very weak SPH Galerkin variant: 0.22 / 0.84 / 0.61, 0.10 / 0.21 / 0.20), with the
//    fixed side faces' reflections inside the window (above) and the square two spacings wide at 0.5.
//  - Cost. Every step and every power iteration is a sparse LU solve with C, whose fill grows fast
//    in 3-D: dx = 0.5 (3375 nodes) takes 16.8 s of set-up, 7.8 s for 104 steps and 254 MiB; dx =
//    0.25 (24,389 nodes) 749 s of CPU (about 560 set-up, 190 for 220 steps) and 4167 MiB, about
//    nodes^1.41, so dx = 0.125 would need about 71 GiB (lamb3d refuses it: drivers/lamb3d/main.cpp).

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
