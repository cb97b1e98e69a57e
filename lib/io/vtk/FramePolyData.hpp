#pragma once
// Internal to lib/io/vtk (included only by its .cpp files, never by a public header): turns a
// ParticleFrame into a vtkPolyData, shared by the .vtp writer and the PNG renderer so both show
// exactly the same points and arrays.

#include "io/vtk/ParticleFrame.hpp"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

namespace mfwave {

// Points padded to 3-D (double precision, so files round-trip exactly), one vtkVertex cell per
// particle (ParaView shows point clouds only through cells), every field as point data (vectors
// padded to 3 components), and the time as field data "TimeValue", which ParaView reads as the
// data set's time. Checks the frame first (checkFrame).
template <int D>
vtkSmartPointer<vtkPolyData> makePolyData(const ParticleFrame<D>& frame);

}  // namespace mfwave
