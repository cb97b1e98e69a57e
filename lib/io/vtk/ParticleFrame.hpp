#pragma once
// What an output plugin sees of one instant: particle positions plus named per-particle fields.
// Deliberately free of VTK types, so a driver or method can describe its output without pulling
// VTK headers into its own translation units; only the .cpp files of this folder talk to VTK.

#include "core/Types.hpp"
#include "particles/ParticleSet.hpp"

#include <string>
#include <vector>

namespace mfwave {

// How a field is shown. Vectors are padded to 3 components on output (a 1-D or 2-D vector gets
// zeros), because ParaView's glyphs and "X/Y/Z/Magnitude" menus expect 3-component vectors.
// Scalars stay 1 component; tensors (6 symmetric XX,YY,ZZ,XY,YZ,XZ or 9 full) are written as-is.
enum class FieldKind { ScalarField, VectorField, TensorField };

// One named per-particle field. `values` is interleaved like the state vectors of the solver:
// values[particle * components + component], for the first `count` particles of the frame.
struct ParticleField {
  std::string name;
  int components = 1;
  FieldKind kind = FieldKind::ScalarField;
  std::vector<Real> values;

  static ParticleField scalar(std::string name, std::vector<Real> values);
  static ParticleField vector(std::string name, int components, std::vector<Real> values);
  static ParticleField tensor(std::string name, int components, std::vector<Real> values);
};

// One frame: the first `count` particles of `positions` (e.g. the physical ones only, leaving
// out ghosts), their fields, and the time. Positions are pointed to, not copied, so a frame of a
// large cloud costs nothing until it is written; the coordinates must outlive the frame.
// With `indices` set, the frame's point p is instead particle (*indices)[p] of `positions`, and
// count must equal indices->size(): the particles one rank owns in a distributed run, written
// without copying their coordinates (the index list must outlive the frame too).
// 1-D and 2-D positions are padded with zeros to 3-D points on output.
template <int D>
struct ParticleFrame {
  const Coordinates<D>* positions = nullptr;
  Index count = 0;
  Real time = 0;
  std::vector<ParticleField> fields;
  const std::vector<Index>* indices = nullptr;  // last: brace initialisers of the others stay valid

  // The field called `name`, or nullptr.
  const ParticleField* find(const std::string& name) const;
};

// Throws Error when the frame is inconsistent: no positions, count larger than a coordinate
// array, an index list of another length than count or with an index outside the coordinates,
// a field whose values do not hold count * components numbers, a vector with more than 3
// components, an empty or repeated field name.
template <int D>
void checkFrame(const ParticleFrame<D>& frame);

// Components of `field` on output: 3 for a vector (padded), its own count otherwise. The .vtp
// writer and the .pvtp master (which must declare the same arrays) both ask here.
int writtenComponents(const ParticleField& field);

// The field of the first `count` particles of a solver state laid out as
// dof = particle * components + component. Throws Error if `state` is shorter than that.
ParticleField fieldFromState(std::string name, const Vector& state, int components, Index count,
                             FieldKind kind);

// How a state with `components` per particle in D dimensions is best shown: D components (also
// 1 in 1-D) is a VectorField (padded to 3); 1 component in 2-D/3-D is a ScalarField (a scalar
// wave equation); anything else a TensorField (written as-is).
FieldKind stateFieldKind(int dimension, int components);

extern template struct ParticleFrame<1>;
extern template struct ParticleFrame<2>;
extern template struct ParticleFrame<3>;

}  // namespace mfwave
