#include "io/vtk/StateFrame.hpp"

#include "core/Error.hpp"

#include <cstdio>
#include <filesystem>
#include <system_error>

namespace mfwave {

template <int D>
ParticleFrame<D> frameFromState(const ParticleSet<D>& particles, const StateView& state, int components,
                                const ExtraFields& extra) {
  const Index c = components;
  if (c < 1) throw Error("frame output: components per particle must be at least 1, got " + std::to_string(c));
  if (state.velocity.size() != state.displacement.size())
    throw Error("frame output: displacement has " + std::to_string(state.displacement.size()) +
                " entries but velocity " + std::to_string(state.velocity.size()));
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
  frame.count = count;
  frame.time = state.time;
  const FieldKind kind = stateFieldKind(D, components);
  frame.fields.push_back(fieldFromState("displacement", state.displacement, components, count, kind));
  frame.fields.push_back(fieldFromState("velocity", state.velocity, components, count, kind));
  if (extra) extra(state, count, frame.fields);
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

}  // namespace mfwave
