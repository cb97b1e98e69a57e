#pragma once
// Builds the ParticleFrame of a solver state: what the frame observers (VtkFrameWriter,
// PngFrameRenderer) share, so a .vtp frame and its PNG always show the same fields.

#include "integrators/Integrator.hpp"
#include "io/vtk/ParticleFrame.hpp"

#include <functional>
#include <string>
#include <vector>

namespace mfwave {

// Lets a method add its own fields (stress, density, ...) to every frame: called with the state
// and the number of particles in the frame; it appends fields of `count` particles.
using ExtraFields = std::function<void(const StateView& state, Index count, std::vector<ParticleField>& fields)>;

// The frame of `state` on `particles`, whose unknowns are laid out as dof = particle *
// components + component (1 for a scalar method, D for elasticity): "displacement" and
// "velocity" (kind stateFieldKind(D, components)), then the extra fields. The state may cover the physical particles (ghosts carry
// no unknowns) or all particles; any other size throws Error naming both. The frame points at
// the particles' coordinates, so it sees moved particles and must not outlive `particles`.
template <int D>
ParticleFrame<D> frameFromState(const ParticleSet<D>& particles, const StateView& state, int components,
                                const ExtraFields& extra = {});

// The frame of a state that holds only the particles `nodes` (in a distributed run, the
// particles a rank owns): node k of the state is particle nodes[k], dof = k * components +
// component. Same fields as above; `extra` is called with this state and nodes.size(), so it
// appends the fields of these nodes only. A state of another size than nodes.size() * components
// throws Error; indices outside the particles throw when the frame is written (checkFrame). The
// frame points at `nodes` and at the particles' coordinates and must outlive neither.
template <int D>
ParticleFrame<D> frameFromState(const ParticleSet<D>& particles, const std::vector<Index>& nodes,
                                const StateView& state, int components, const ExtraFields& extra = {});

// "<folder>/<base>_<NNNNNN><extension>" with the frame number zero-padded to 6 digits, so the
// files sort in time order.
std::string frameFilePath(const std::string& folder, const std::string& base, long frame,
                          const std::string& extension);

// Creates `folder` and its parents if missing; throws Error naming it if that fails.
void ensureFolder(const std::string& folder);

}  // namespace mfwave
