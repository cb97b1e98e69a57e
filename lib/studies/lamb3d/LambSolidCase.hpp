#pragma once
// One updated-Lagrangian SPH case of the lamb2d or lamb3d study: the plane-strain or 3-D Lamb problem
// of the scene (one implementation for D = 2 and 3; the 2-D figures first, the 3-D ones after them)
// by the SPH for solids of Li's primer (eqs. 17-30: continuity density, stiffened-gas EOS with
// gamma = 1, Jaumann hypoelasticity, Monaghan's momentum equation; lib/methods/updated_lagrangian_sph),
// a large-deformation method, run at small amplitude so that it answers the linear problem, scored
// against the same exact response as the very weak SPH and RK collocation cases.
//
//   particles    the scene's rectangle lattice (buildParticles, physical particles only, as the RK
//                case's nodes), m = rho0 dx^2 each (tributary: below)
//   load         UpdatedLagrangianSph::addTraction on the loaded face's particles: the force on a
//                particle is eps T f(t) times the length of its tributary segment [x - dx/2, x + dx/2]
//                (clipped to the box) inside the strip, so the strip's end particles (at x = +-0.5
//                when dx divides 0.5) carry half, and the total force is eps * width * T * f(t)
//                exactly (patchTraction; the case's notes say it). In 3-D the segment is the square
//                [x +- dx/2] x [y +- dx/2] clipped to the face and the patch, so the total force is
//                eps * patch area * T * f(t)
//   small amplitude  eps = method.ul_amplitude (1e-4): strains ~ 1e-4 keep the EOS and the Jaumann
//                rate linear to ~1e-4; the probes record v / eps
//   faces        every face free (the method has no dashpot): the scene's transmitting faces are
//                free ones here; the first P wave they reflect reaches a probe at t = 7.8 on
//                data/scenes/lamb2d.toml, after the error window 6 (firstReflection; the notes say
//                it). A free body takes the load's net impulse: after the waves reach the faces it
//                drifts (rigid velocity 1 / (rho * 16 * 8) = 0.0078 per unit eps after the pulse),
//                which the errors within the window do not see.
//
// Choices (UpdatedLagrangianSphOptions' defaults unless said; LambSolidSpec::linearDefaults). Measured
// on data/scenes/lamb2d.toml, relative L2 at centre / receiver / buried over 0 <= t <= 6:
//   kernel          cubic_spline, h / dx = 1.3 (the usual UL-SPH ratio; the options' default; the ratio
//                   passed to the method is rescaled for the faces' smaller volumes: lambSolidOptions)
//   density         continuity (eq. 18; summation loses half its support at the free surface)
//   EOS             gamma = 1 (isothermal): p = c0^2 (rho - rho0), c0^2 = K / rho0; with the Jaumann
//                   rate (eq. 26, shear modulus G) this is plane-strain linear elasticity at small
//                   amplitude (eps = 1e-6, 1e-4, 1e-2 give the same errors to 1e-4, 1e-4, 1e-2)
//   masses          tributary areas (face particles half, corners a quarter; method.ul_tributary_volumes)
//   kernel-gradient correction  on (method.kernel_gradient_correction): the velocity gradient and the
//                   stress divergence of a free-surface particle, whose support is cut in half, are
//                   then first-order consistent
//   artificial viscosity  alpha = 1, beta = 0 (method.viscosity_alpha / _beta). The problem is
//                   linear, but without viscosity the free surface rings (with or without the
//                   correction): after the pulse the load centre oscillates at about 0.2 of the peak
//                   with a period near 2.2, and a slow spurious surface wave reaches the receiver at
//                   t ~ 5. Monaghan's Pi_ij (O(h)) damps it. Centre / receiver / buried:
//                     alpha = 0    dx 0.5: 2.04 / 1.00 / 1.07   0.25: 0.59 / 0.88 / 0.50
//                                  0.125: 0.72 / 0.38 / 0.18    0.0625: 0.102 / 0.148 / 0.077
//                     alpha = 0.1  dx 0.5: 1.87 / 0.96 / 1.01   0.25: 0.50 / 0.87 / 0.47
//                                  0.125: 0.46 / 0.38 / 0.15    0.0625: 0.074 / 0.145 / 0.060
//                     alpha = 1    dx 0.5: 1.08 / 0.86 / 0.67   0.25: 0.28 / 0.79 / 0.33
//                                  0.125: 0.13 / 0.35 / 0.10    0.0625: 0.056 / 0.134 / 0.044
//                   (alpha = 0.5 and 2, run with h = 1.3 sqrt(mean volume), 3 % under 1.3 dx at 0.25:
//                   0.34 / 0.81 / 0.36 and 0.25 / 0.72 / 0.28 at 0.25, 0.059 / 0.137 / 0.046 and
//                   0.055 / 0.139 / 0.052 at 0.0625: alpha = 1 is near the best.)
//                   With full masses dx^2 on the faces and no correction (alpha = 1): 0.26 / 0.85 /
//                   0.44, 0.13 / 0.47 / 0.17, 0.056 / 0.158 / 0.064; alpha = 0 there: 0.59 / 1.10 /
//                   0.76, 0.19 / 0.55 / 0.23. The receiver, 2 along the surface, is the worst at every
//                   setting: the Rayleigh pulse arrives weak and late on a coarse lattice.
//   artificial stress     off (no tension large enough for the tensile instability at eps = 1e-4)
//   XSPH            off (it smooths the velocity the probes read)
//   integrator      leapfrog (SplitLeapfrog: the kick-drift-kick staggered scheme SPH codes use for
//                   solids) at the method's own step, recomputed every step: courant 0.3 h / (c + 1.2 alpha c), c the EOS speed
//                   stiffened by the shear modulus (c_p), and 0.25 sqrt(h / max|a|) (never the smaller
//                   at this amplitude); the scene's integrator.name / cfl (central difference for the
//                   very weak SPH) are not used (the driver says so in a note)
// Cost (alpha = 1, one thread): dx = 0.5: 561 particles, 117 steps, 0.06 s; 0.25: 2145, 234, 0.4 s;
// 0.125: 8385, 469, 3.5 s; 0.0625: 33153, 938, 29 s (the viscous term halves the step: alpha = 0 takes
// 426 steps, 13 s at 0.0625). The receiver's arrival error (0.6 s at every spacing) is the threshold's:
// the exact response's P precursor dips to -0.023 at t = 1.7, past 0.1 of its peak, and the method's
// to -0.014; the Rayleigh pulse itself arrives on time at dx = 0.0625.
// Long run (dx = 0.125, t = 300, alpha = 1): exit 0, the stability monitor silent; the largest |v| / eps
// per interval falls (centre 0.58 over the window, 0.11 to t = 50, 0.042 over 200 - 300) around the
// free body's drift 0.0077. With alpha = 0 (10659 steps, 75 s) also exit 0, but nothing removes the
// energy: the largest |v| / eps stays near 0.29 at the centre and 0.16 - 0.19 at the others to t = 300.
//
// In 3-D (data/scenes/lamb3d.toml: the square |x|, |y| < 0.5 on the 7 x 7 x 7 block; lamb3d) the same
// method and choices, not re-tuned (alpha = 1 and the correction from the 2-D measurements), tributary
// volumes dx^3 halved once per face (faces 1/2, edges 1/4, corners 1/8). Relative L2 centre /
// receiver / buried over 0 <= t <= 6:
//   box    the scene's 7 x 7 x 7, every face free. Its +x face reflects the first P wave to the
//          receiver at t = 4.5 / c_p = 2.6, inside the window (the note says so); on the scene's
//          13 x 13 x 7 free block (study.free_block_lower / _upper, the very weak SPH's comparison)
//          at 10.5 / c_p = 6.06, after it. Measured both ways:
//            7-box   dx 0.5: 1.323 / 0.882 / 1.128 (3375 particles)   0.25: 0.377 / 0.904 / 0.634 (24389)
//                    0.125: 0.162 / 0.438 / 0.194 (185193)
//            13-box  dx 0.5: 1.323 / 0.889 / 1.119 (10935)            0.25: 0.377 / 0.916 / 0.636 (81461)
//                    (0.125 not run: 628425 particles, about 30 minutes on one free core)
//          The reflections change the probes by 0.6 %, 5.8 %, 2.8 % (0.5) and 0.8 %, 5.1 %, 4.7 %
//          (0.25) of the exact response's norm (|v7 - v13| over 1 % of the exact peak from t = 3.1 at
//          the receiver, 4.7 buried), small beside the method's own error, and the errors move by
//          0.012 at most (the receiver is slightly better in the 7-box): the 13-box costs 3.3 times the
//          particles for nothing, so the case runs the scene's box (the driver ignores the free block
//          with a note). The drift of the free body: 1 / 343 = 0.0029 per unit eps after the pulse.
//   errors  fall with dx at every probe, but stay above the 2-D ones at the same spacing (0.28 / 0.79 /
//          0.33 at 0.25, 0.13 / 0.35 / 0.10 at 0.125 there): the square is
//          2 spacings wide at dx = 0.5 and 4 at 0.25, the centre overshoots its peak (0.73 against
//          0.42 at 0.5, +11 % at 0.25) and rings after the pulse with a period of about 1.9, as the 2-D
//          free surface does, and the receiver's Rayleigh pulse arrives weak (peak -62 % at 0.25).
//          The buried probe, 2 spacings under the load at 0.5, is 1.13 there, 0.63 at 0.25.
//   cost   (one thread, on a machine shared with other jobs, so the wall times are upper bounds):
//          dx = 0.5: 3375 particles, 117 steps, 3.5 s, 38 MiB; 0.25: 24389, 234, 131 s, 75 MiB (the
//          13-box: 11 s, 52 MiB and 496 s, 178 MiB); 0.125: 185193, 469, 820 s (538 s of CPU: 1.6e5
//          particle-steps per second), 365 MiB. About 97 neighbours at 0.5, 109 at 0.25, 116 at 0.125
//          (28 in 2-D: h / dx = 1.3).
//   long run  dx = 0.5 to t = 300 (50 windows; 5862 steps, 230 s on the shared machine, 39 MiB): exit 0,
//          the stability monitor silent; the largest |v| / eps per interval falls (centre 0.90 over the
//          window, 0.069 to t = 50, 0.012 over 50 - 100, 0.0046 over 200 - 300; receiver 0.022 and
//          0.0040, buried 0.088 and 0.0046 over 6 - 50 and 200 - 300) onto the free body's drift: the mean over 200 - 300 is 0.00293 at every probe
//          (1 / 343 = 0.00292). The errors in the window are those of the short run, to every digit.
// StabilityMonitor watches u = x - X and v of every particle (through SolidStateAdapter) and stops a
// run that blows up (InstabilityError, exit 3) naming the particle and its position.

#include "studies/lamb3d/LambCase.hpp"

#include "io/scene/GeometrySpec.hpp"
#include "io/scene/LoadSpec.hpp"
#include "methods/updated_lagrangian_sph/UpdatedLagrangianSph.hpp"
#include "particles/ParticleSet.hpp"

#include <string>
#include <vector>

namespace mfwave::lamb3d {

// The particles of a surface_patch load's face that carry its traction, each with the measure of
// its tributary facet inside the patch: a length in 2-D (the patch is a segment of an edge), an area
// in 3-D (a rectangle of a face).
struct PatchTraction {
  std::vector<Index> particles;
  std::vector<Real> measures;
  Real totalMeasure() const;
};

// `load` a surface_patch load, `particles` the lattice (spacing dx) its face is part of. A face
// particle's tributary facet is [x - dx/2, x + dx/2] along each axis of the face, clipped to the
// face and to the patch; the particles whose facet misses the patch are left out.
template <int D>
PatchTraction patchTraction(const LoadSpec& load, const ParticleSet<D>& particles, Real dx);

// The case's particles: the physical lattice of `geometry` (no ghosts), with tributary volumes when
// asked (dx^D halved once per face the particle lies on).
template <int D>
ParticleSet<D> lambSolidParticles(const GeometrySpec& geometry, bool tributaryVolumes);

// The method's options for these particles: spec.options with h = smoothingLengthRatio * dx (the
// method measures its spacing from the mean volume, which tributary volumes make smaller than dx).
template <int D>
UpdatedLagrangianSphOptions lambSolidOptions(const LambSolidSpec& spec, const ParticleSet<D>& particles, Real dx);

// The load on the system: amplitude * traction * f(t) * measure on each particle of `patch`.
template <int D>
void applyPatchLoad(UpdatedLagrangianSph<D>& system, const LoadSpec& load, const PatchTraction& patch, Real amplitude);

// Runs the updated-Lagrangian SPH case `settings` (settings.solid set) of a 2-D or 3-D scene with one
// surface_patch load, on the lattice of settings.geometry (the driver's choice of box). Throws
// InputError("method.name") for another dimension, InputError("load") without such a load, and
// InstabilityError (naming the particle and its position) on a blow-up.
CaseResult runSolidCase(const StudySettings& study, const CaseSettings& settings, const std::string& folder,
                        bool progress);

}  // namespace mfwave::lamb3d
