#pragma once
// Reading a closed surface mesh (STL, OBJ or VTK XML poly data .vtp) into a TriangleMesh solid.
// Part of the separate target mfwave::geometry_vtk, so programs that read no meshes link no VTK;
// this header carries no VTK types.
//
// VTK's readers (vtkSTLReader, vtkOBJReader, vtkXMLPolyDataReader) read the file; the polygons are
// triangulated and the points cleaned (duplicates merged: STL stores every triangle's corners
// anew, so without merging no edge would be shared and every mesh would look open).

#include "geometry/TriangleMesh.hpp"

#include <string>

namespace mfwave {

// The format follows the extension (.stl, .obj, .vtp; any case). Throws InputError(path, ...) for
// an unknown extension, a file that cannot be read or holds no triangles, and for every refusal
// of TriangleMesh (an open mesh names its boundary edges), so the error names the file.
TriangleMesh readSurfaceMesh(const std::string& path, const std::string& name = "");

}  // namespace mfwave
