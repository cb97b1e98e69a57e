// Reading surface meshes through VTK: an ASCII STL cube (written here, its corners repeated per
// triangle as STL does) becomes a closed mesh of the right volume; a tetrahedron's OBJ and a
// cube of quadrilaterals in a .vtp (triangulated on reading) too; an STL with a face missing, a missing file and an unknown extension are refused naming the file.

#include "core/Error.hpp"
#include "geometry/SurfaceMeshFile.hpp"

#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

using namespace mfwave;

namespace {

// A folder of its own under the system's temporary directory, removed afterwards.
class MeshFolder {
 public:
  MeshFolder() {
    path_ = std::filesystem::temp_directory_path() / ("mfwave_mesh_" + std::to_string(::getpid()));
    std::filesystem::create_directories(path_);
  }
  ~MeshFolder() { std::filesystem::remove_all(path_); }
  MeshFolder(const MeshFolder&) = delete;
  MeshFolder& operator=(const MeshFolder&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

// The unit cube's 12 triangles, outward, as corner coordinates.
std::vector<std::array<Vec3, 3>> cubeFacets() {
  std::vector<Vec3> v;
  for (int k = 0; k < 8; ++k) v.emplace_back(k & 1 ? 1.0 : 0.0, k & 2 ? 1.0 : 0.0, k & 4 ? 1.0 : 0.0);
  const int faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  std::vector<std::array<Vec3, 3>> facets;
  for (const auto& f : faces) {
    facets.push_back({v[static_cast<std::size_t>(f[0])], v[static_cast<std::size_t>(f[1])], v[static_cast<std::size_t>(f[2])]});
    facets.push_back({v[static_cast<std::size_t>(f[0])], v[static_cast<std::size_t>(f[2])], v[static_cast<std::size_t>(f[3])]});
  }
  return facets;
}

void writeAsciiStl(const std::string& path, const std::vector<std::array<Vec3, 3>>& facets) {
  std::ofstream out(path);
  out << "solid cube\n";
  for (const auto& f : facets) {
    const Vec3 n = (f[1] - f[0]).cross(f[2] - f[0]).normalized();
    out << "  facet normal " << n.x() << ' ' << n.y() << ' ' << n.z() << "\n    outer loop\n";
    for (const Vec3& p : f) out << "      vertex " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    out << "    endloop\n  endfacet\n";
  }
  out << "endsolid cube\n";
}

template <class F>
std::string meshFileKey(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.key() + " | " + e.problem();
  }
  return "";
}

}  // namespace

TEST(SurfaceMeshFile, ReadsAnAsciiStlCube) {
  const MeshFolder folder;
  const std::string path = folder.file("cube.stl");
  writeAsciiStl(path, cubeFacets());
  const TriangleMesh cube = readSurfaceMesh(path, "part");
  EXPECT_EQ(cube.vertices().size(), 8u);  // the 36 corners merged
  EXPECT_EQ(cube.triangles().size(), 12u);
  EXPECT_NEAR(cube.volume(), 1.0, 1e-12);
  EXPECT_LT(cube.signedDistance(Vec3(0.5, 0.5, 0.5)), 0);
  EXPECT_NEAR(cube.signedDistance(Vec3(0.5, 0.5, 1.2)), 0.2, 1e-7);  // STL stores floats
  EXPECT_EQ(cube.surfaceName(Vec3(0, 0, 0)), "part.surface");
}

TEST(SurfaceMeshFile, ReadsAnObjTetrahedron) {
  const MeshFolder folder;
  const std::string path = folder.file("tet.OBJ");
  std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";
  const TriangleMesh tet = readSurfaceMesh(path);
  EXPECT_NEAR(tet.volume(), 1.0 / 6, 1e-14);
  EXPECT_LT(tet.signedDistance(Vec3(0.1, 0.1, 0.1)), 0);
}

TEST(SurfaceMeshFile, ReadsAndTriangulatesAVtpOfQuadrilaterals) {
  const MeshFolder folder;
  const std::string path = folder.file("cube.vtp");
  vtkNew<vtkPoints> points;
  for (int k = 0; k < 8; ++k) points->InsertNextPoint(k & 1 ? 2.0 : 0.0, k & 2 ? 1.0 : 0.0, k & 4 ? 1.0 : 0.0);
  vtkNew<vtkCellArray> quads;
  const vtkIdType faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& f : faces) quads->InsertNextCell(4, f);
  vtkNew<vtkPolyData> box;
  box->SetPoints(points);
  box->SetPolys(quads);
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(box);
  ASSERT_EQ(writer->Write(), 1);
  const TriangleMesh mesh = readSurfaceMesh(path);
  EXPECT_EQ(mesh.triangles().size(), 12u);
  EXPECT_NEAR(mesh.volume(), 2.0, 1e-14);
  EXPECT_NEAR(mesh.area(), 10.0, 1e-14);
}

TEST(SurfaceMeshFile, RefusesAnOpenMeshAndBadFilesNamingThem) {
  const MeshFolder folder;
  const std::string path = folder.file("open.stl");
  std::vector<std::array<Vec3, 3>> facets = cubeFacets();
  facets.pop_back();
  writeAsciiStl(path, facets);
  const std::string open = meshFileKey([&] { readSurfaceMesh(path); });
  EXPECT_EQ(open.rfind(path + " | ", 0), 0u) << open;
  EXPECT_NE(open.find("3 boundary edges"), std::string::npos) << open;

  const std::string missing = folder.file("missing.stl");
  EXPECT_EQ(meshFileKey([&] { readSurfaceMesh(missing); }).rfind(missing + " | ", 0), 0u);
  const std::string unknown = folder.file("cube.ply");
  std::ofstream(unknown) << "ply\n";
  EXPECT_NE(meshFileKey([&] { readSurfaceMesh(unknown); }).find("unknown surface mesh format"), std::string::npos);
  const std::string garbage = folder.file("garbage.vtp");
  std::ofstream(garbage) << "this is not XML\n";
  const std::string unreadable = meshFileKey([&] { readSurfaceMesh(garbage); });
  EXPECT_EQ(unreadable.rfind(garbage + " | VTK could not read", 0), 0u) << unreadable;
}
