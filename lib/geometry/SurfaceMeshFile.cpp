#include "geometry/SurfaceMeshFile.hpp"

#include "core/Error.hpp"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCleanPolyData.h>
#include <vtkCommand.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>
#include <vtkXMLPolyDataReader.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <string>
#include <vector>

namespace mfwave {
namespace {

// VTK reports a bad file through an error event (printed, not thrown); an observer keeps the text so
// the exception can say it, and stops VTK printing it.
void keepVtkMessage(vtkObject*, unsigned long, void* clientData, void* callData) {
  auto* message = static_cast<std::string*>(clientData);
  if (message->empty() && callData != nullptr) *message = static_cast<const char*>(callData);
}

std::string lowerCaseExtension(const std::string& path) {
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

vtkSmartPointer<vtkAlgorithm> meshReader(const std::string& path) {
  const std::string ext = lowerCaseExtension(path);
  if (ext == "stl") {
    auto reader = vtkSmartPointer<vtkSTLReader>::New();
    reader->SetFileName(path.c_str());
    return reader;
  }
  if (ext == "obj") {
    auto reader = vtkSmartPointer<vtkOBJReader>::New();
    reader->SetFileName(path.c_str());
    return reader;
  }
  if (ext == "vtp") {
    auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    reader->SetFileName(path.c_str());
    return reader;
  }
  throw InputError(path, "unknown surface mesh format '." + ext + "': expected .stl, .obj or .vtp");
}

}  // namespace

TriangleMesh readSurfaceMesh(const std::string& path, const std::string& name) {
  if (!std::ifstream(path).good()) throw InputError(path, "cannot open the surface mesh file");
  vtkSmartPointer<vtkAlgorithm> reader = meshReader(path);

  std::string message;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetCallback(keepVtkMessage);
  onError->SetClientData(&message);
  reader->AddObserver(vtkCommand::ErrorEvent, onError);

  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(reader->GetOutputPort());
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  triangles->AddObserver(vtkCommand::ErrorEvent, onError);
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputConnection(triangles->GetOutputPort());
  clean->PointMergingOn();
  clean->SetTolerance(0.0);  // exact duplicates: what STL repeats
  clean->ConvertPolysToLinesOff();
  clean->ConvertStripsToPolysOff();
  clean->AddObserver(vtkCommand::ErrorEvent, onError);
  clean->Update();
  if (!message.empty()) throw InputError(path, "VTK could not read the surface mesh: " + message);

  vtkPolyData* mesh = clean->GetOutput();
  std::vector<Vec3> vertices(static_cast<std::size_t>(mesh->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i) {
    double p[3];
    mesh->GetPoint(i, p);
    vertices[static_cast<std::size_t>(i)] = Vec3(p[0], p[1], p[2]);
  }
  std::vector<std::array<Index, 3>> faces;
  vtkCellArray* polys = mesh->GetPolys();
  faces.reserve(static_cast<std::size_t>(polys->GetNumberOfCells()));
  vtkNew<vtkIdList> cell;
  for (polys->InitTraversal(); polys->GetNextCell(cell);) {
    if (cell->GetNumberOfIds() != 3) continue;  // degenerate leftovers of cleaning
    faces.push_back({static_cast<Index>(cell->GetId(0)), static_cast<Index>(cell->GetId(1)),
                     static_cast<Index>(cell->GetId(2))});
  }
  if (faces.empty()) throw InputError(path, "the file holds no triangles");
  try {
    return TriangleMesh(std::move(vertices), std::move(faces), name);
  } catch (const InputError& e) {
    throw InputError(path, e.problem());
  }
}

}  // namespace mfwave
