#pragma once
// One spectral-element case of the lamb2d or lamb3d study: the plane-strain or 3-D Lamb problem of
// the scene by the seismologists' reference scheme (SEM as in SPECFEM2D / SPECFEM3D: GLL nodes of
// order N per square / cubic element, sum-factorised stiffness,
// GLL quadrature, lumped mass, central difference; lib/methods/spectral_element), scored against the
// same exact response as the very weak SPH and RK collocation cases (scoreLambProbes), so the
// "which method for which problem" page compares like with like.
//
//   mesh       square / cubic elements of side N * geometry.spacing over the scene's box, so the mean
//              node spacing is the lattice spacing of the other methods (the rectangle must be a
//              whole number of elements: InputError("geometry.spacing") otherwise)
//   faces      the scene's transmitting faces become Lysmer-Kuhlemeyer dashpots on the GLL nodes,
//              fixed faces u = 0, the others free (natural)
//   load       the surface_patch traction T f(t) on |x - centre| < half_width (a strip in 2-D, a
//              rectangle in 3-D), integrated exactly
//              against the basis (the face's GLL rule when the strip's ends are element boundaries,
//              as from spacing 0.125 with N = 4; Gauss-Legendre on the loaded part of an edge when
//              they fall inside an element, as at spacing 0.25 with N = 4, elements of side 1;
//              tensor Gauss-Legendre over the loaded part of each face element in 3-D)
//   step       integrator.cfl times 2 / omega_max, omega_max^2 by power iteration on M^-1 K
//   probes     the GLL node nearest each probe (data/scenes/lamb2d.toml's (0, 0), (2, 0), (0, -1) are
//              element corners whenever N * spacing divides them; a probe off the nodes is noted)
// The energy ledger and the stability monitor run as in the very weak SPH case; no frames.

#include "studies/lamb3d/LambCase.hpp"

#include <string>

namespace mfwave::lamb3d {

// Runs the spectral-element case `settings` (settings.spectralElementOrder set) of a 2-D or 3-D scene
// with one surface_patch load. Throws InputError("scene.dimension") for another dimension, InputError("load")
// without such a load, InputError("geometry.spacing") when the rectangle is not a whole number of
// elements, InputError("boundary[i].type") for a face type the case does not run, InputError on
// the step limit (checkStepLimit) and InstabilityError when the run blows up.
CaseResult runSpectralElementCase(const StudySettings& study, const CaseSettings& settings, const std::string& folder,
                                  bool progress);

}  // namespace mfwave::lamb3d
