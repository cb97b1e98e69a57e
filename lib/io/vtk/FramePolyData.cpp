#include "io/vtk/FramePolyData.hpp"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

#include <algorithm>

namespace mfwave {

namespace {

vtkSmartPointer<vtkDoubleArray> toArray(const ParticleField& field, Index count) {
  // Vectors get 3 components whatever the dimension; the missing ones stay zero.
  const int written = writtenComponents(field);
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(field.name.c_str());
  array->SetNumberOfComponents(written);
  array->SetNumberOfTuples(static_cast<vtkIdType>(count));
  double* out = array->GetPointer(0);
  const auto n = static_cast<std::size_t>(count);
  const auto in = static_cast<std::size_t>(field.components);
  const auto w = static_cast<std::size_t>(written);
  for (std::size_t p = 0; p < n; ++p)
    for (std::size_t c = 0; c < w; ++c) out[p * w + c] = c < in ? field.values[p * in + c] : 0.0;
  return array;
}

}  // namespace

template <int D>
vtkSmartPointer<vtkPolyData> makePolyData(const ParticleFrame<D>& frame) {
  checkFrame(frame);
  const auto n = static_cast<std::size_t>(frame.count);

  auto coordinates = vtkSmartPointer<vtkDoubleArray>::New();
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(static_cast<vtkIdType>(n));
  double* xyz = coordinates->GetPointer(0);
  std::fill(xyz, xyz + 3 * n, 0.0);  // the axes beyond D stay zero
  for (std::size_t a = 0; a < static_cast<std::size_t>(D); ++a) {
    const std::vector<Real>& axis = (*frame.positions)[a];
    if (frame.indices != nullptr)
      for (std::size_t p = 0; p < n; ++p) xyz[3 * p + a] = axis[static_cast<std::size_t>((*frame.indices)[p])];
    else
      for (std::size_t p = 0; p < n; ++p) xyz[3 * p + a] = axis[p];
  }
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetData(coordinates);

  // One vertex per particle, built directly as offsets 0..n and connectivity 0..n-1.
  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  offsets->SetNumberOfTuples(static_cast<vtkIdType>(n + 1));
  connectivity->SetNumberOfTuples(static_cast<vtkIdType>(n));
  for (std::size_t p = 0; p <= n; ++p) offsets->SetValue(static_cast<vtkIdType>(p), static_cast<vtkIdType>(p));
  for (std::size_t p = 0; p < n; ++p) connectivity->SetValue(static_cast<vtkIdType>(p), static_cast<vtkIdType>(p));
  auto vertices = vtkSmartPointer<vtkCellArray>::New();
  vertices->SetData(offsets, connectivity);

  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetVerts(vertices);
  for (const auto& field : frame.fields) polyData->GetPointData()->AddArray(toArray(field, frame.count));

  auto time = vtkSmartPointer<vtkDoubleArray>::New();
  time->SetName("TimeValue");
  time->SetNumberOfTuples(1);
  time->SetValue(0, frame.time);
  polyData->GetFieldData()->AddArray(time);
  return polyData;
}

template vtkSmartPointer<vtkPolyData> makePolyData(const ParticleFrame<1>&);
template vtkSmartPointer<vtkPolyData> makePolyData(const ParticleFrame<2>&);
template vtkSmartPointer<vtkPolyData> makePolyData(const ParticleFrame<3>&);

}  // namespace mfwave
