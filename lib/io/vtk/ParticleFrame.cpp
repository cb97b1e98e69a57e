#include "io/vtk/ParticleFrame.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <set>

namespace mfwave {

ParticleField ParticleField::scalar(std::string name, std::vector<Real> values) {
  return {std::move(name), 1, FieldKind::ScalarField, std::move(values)};
}

ParticleField ParticleField::vector(std::string name, int components, std::vector<Real> values) {
  return {std::move(name), components, FieldKind::VectorField, std::move(values)};
}

ParticleField ParticleField::tensor(std::string name, int components, std::vector<Real> values) {
  return {std::move(name), components, FieldKind::TensorField, std::move(values)};
}

template <int D>
const ParticleField* ParticleFrame<D>::find(const std::string& name) const {
  for (const auto& field : fields)
    if (field.name == name) return &field;
  return nullptr;
}

template <int D>
void checkFrame(const ParticleFrame<D>& frame) {
  if (frame.positions == nullptr) throw Error("particle frame: no positions");
  if (frame.count < 0) throw Error("particle frame: negative particle count " + std::to_string(frame.count));
  if (frame.indices != nullptr && static_cast<Index>(frame.indices->size()) != frame.count)
    throw Error("particle frame: " + std::to_string(frame.indices->size()) + " particle indices for count " +
                std::to_string(frame.count));
  // The largest coordinate index the frame reads: count - 1, or the largest of its indices.
  Index last = frame.count - 1;
  if (frame.indices != nullptr && !frame.indices->empty()) {
    const auto [low, high] = std::minmax_element(frame.indices->begin(), frame.indices->end());
    if (*low < 0) throw Error("particle frame: negative particle index " + std::to_string(*low));
    last = *high;
  }
  for (int a = 0; a < D; ++a) {
    const auto available = static_cast<Index>((*frame.positions)[static_cast<std::size_t>(a)].size());
    if (last >= available)
      throw Error("particle frame: " +
                  (frame.indices != nullptr ? "particle index " + std::to_string(last)
                                            : "count " + std::to_string(frame.count)) +
                  " exceeds the " + std::to_string(available) + " coordinates on axis " + std::to_string(a));
  }
  std::set<std::string> names;
  for (const auto& field : frame.fields) {
    if (field.name.empty()) throw Error("particle frame: a field has no name");
    if (!names.insert(field.name).second) throw Error("particle frame: field '" + field.name + "' appears twice");
    if (field.components < 1)
      throw Error("particle frame: field '" + field.name + "' has " + std::to_string(field.components) +
                  " components");
    if (field.kind == FieldKind::ScalarField && field.components != 1)
      throw Error("particle frame: scalar field '" + field.name + "' has " + std::to_string(field.components) +
                  " components");
    if (field.kind == FieldKind::VectorField && field.components > 3)
      throw Error("particle frame: vector field '" + field.name + "' has " + std::to_string(field.components) +
                  " components (at most 3)");
    const auto expected = static_cast<std::size_t>(frame.count) * static_cast<std::size_t>(field.components);
    if (field.values.size() != expected)
      throw Error("particle frame: field '" + field.name + "' holds " + std::to_string(field.values.size()) +
                  " values, expected " + std::to_string(expected) + " (" + std::to_string(frame.count) +
                  " particles x " + std::to_string(field.components) + " components)");
  }
}

int writtenComponents(const ParticleField& field) {
  return field.kind == FieldKind::VectorField ? 3 : field.components;
}

ParticleField fieldFromState(std::string name, const Vector& state, int components, Index count, FieldKind kind) {
  if (components < 1) throw Error("field '" + name + "': components must be at least 1");
  const Index needed = count * components;
  if (state.size() < needed)
    throw Error("field '" + name + "': state has " + std::to_string(state.size()) + " entries, " +
                std::to_string(count) + " particles x " + std::to_string(components) + " components need " +
                std::to_string(needed));
  return {std::move(name), components, kind, std::vector<Real>(state.data(), state.data() + needed)};
}

FieldKind stateFieldKind(int dimension, int components) {
  if (components == dimension) return FieldKind::VectorField;
  if (components == 1) return FieldKind::ScalarField;
  return FieldKind::TensorField;
}

template struct ParticleFrame<1>;
template struct ParticleFrame<2>;
template struct ParticleFrame<3>;
template void checkFrame(const ParticleFrame<1>&);
template void checkFrame(const ParticleFrame<2>&);
template void checkFrame(const ParticleFrame<3>&);

}  // namespace mfwave
