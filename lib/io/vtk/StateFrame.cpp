#include "io/vtk/StateFrame.hpp"

#include "core/Error.hpp"

#include <cstdio>
#include <filesystem>
#include <system_error>

namespace mfwave {

namespace {

void checkState(const StateView& state, int components) {
  if (components < 1)
    throw Error("frame output: components per particle must be at least 1, got " + std::to_string(components));
  if (state.velocity.size() != state.displacement.size())
    throw Error("frame output: displacement has " + std::to_string(state.displacement.size()) +
                " entries but velocity " + std::to_string(state.velocity.size()));
}

// The fields every frame of a state carries, for `count` particles: displacement, velocity, extra.
template <int D>
void addStateFields(ParticleFrame<D>& frame, const StateView& state, int components, Index count,
                    const ExtraFields& extra) {
  frame.count = count;
  frame.time = state.time;
  const FieldKind kind = stateFieldKind(D, components);
  frame.fields.push_back(fieldFromState("displacement", state.displacement, components, count, kind));
  frame.fields.push_back(fieldFromState("velocity", state.velocity, components, count, kind));
  if (extra) extra(state, count, frame.fields);
}

}  // namespace

template <int D>
ParticleFrame<D> frameFromState(const ParticleSet<D>& particles, const StateView& state, int components,
                                const ExtraFields& extra) {
  checkState(state, components);
  const Index c = components;
  Index count = 0;
  if (state.displacement.size() == particles.physicalCount() * c)
    count = particles.physicalCount();
  else if (state.displacement.size() == particles.size() * c)
    count = particles.size();
  else
    throw Error("frame output: state of size " + std::to_string(state.displacement.size()) + " does not fit " +
                std::to_string(particles.physicalCount()) + " physical (" + std::to_string(particles.size()) +
                " total) particles x " + std::to_string(c) + " components");

  ParticleFrame<D> frame;
  frame.positions = &particles.coordinates();
  addStateFields(frame, state, components, count, extra);
  return frame;
}

template <int D>
ParticleFrame<D> frameFromState(const ParticleSet<D>& particles, const std::vector<Index>& nodes,
                                const StateView& state, int components, const ExtraFields& extra) {
  checkState(state, components);
  const auto count = static_cast<Index>(nodes.size());
  if (state.displacement.size() != count * components)
    throw Error("frame output: state of size " + std::to_string(state.displacement.size()) + " does not fit " +
                std::to_string(count) + " owned particles x " + std::to_string(components) + " components");

  ParticleFrame<D> frame;
  frame.positions = &particles.coordinates();
  frame.indices = &nodes;
  addStateFields(frame, state, components, count, extra);
  return frame;
}

std::string frameFilePath(const std::string& folder, const std::string& base, long frame,
                          const std::string& extension) {
  char number[32];
  std::snprintf(number, sizeof number, "%06ld", frame);
  return (std::filesystem::path(folder) / (base + "_" + number + extension)).string();
}

void ensureFolder(const std::string& folder) {
  if (folder.empty()) return;
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) throw Error("cannot create output folder '" + folder + "': " + error.message());
  if (!std::filesystem::is_directory(folder)) throw Error("output folder '" + folder + "' is not a folder");
}

template ParticleFrame<1> frameFromState(const ParticleSet<1>&, const StateView&, int, const ExtraFields&);
template ParticleFrame<2> frameFromState(const ParticleSet<2>&, const StateView&, int, const ExtraFields&);
template ParticleFrame<3> frameFromState(const ParticleSet<3>&, const StateView&, int, const ExtraFields&);
template ParticleFrame<1> frameFromState(const ParticleSet<1>&, const std::vector<Index>&, const StateView&, int,
                                         const ExtraFields&);
template ParticleFrame<2> frameFromState(const ParticleSet<2>&, const std::vector<Index>&, const StateView&, int,
                                         const ExtraFields&);
template ParticleFrame<3> frameFromState(const ParticleSet<3>&, const std::vector<Index>&, const StateView&, int,
                                         const ExtraFields&);

}  // namespace mfwave
