// Closed, consistently oriented surfaces: a tetrahedron passes; an open one (a face missing), one
// face flipped, an edge of three triangles and bad indices are refused with what is wrong.

#include "core/Error.hpp"
#include "geometry/MeshTopology.hpp"

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

using namespace mfwave;

namespace {

std::vector<std::array<Index, 3>> tetrahedron() { return {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}; }

template <class F>
std::string topologyProblem(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "mesh.triangles");
    return e.problem();
  }
  return "";
}

}  // namespace

TEST(MeshTopology, AClosedOrientedTetrahedronPasses) {
  EXPECT_NO_THROW(checkClosedOrientedSurface(4, tetrahedron(), "mesh.triangles"));
}

TEST(MeshTopology, AnOpenMeshNamesItsBoundaryEdges) {
  auto open = tetrahedron();
  open.pop_back();
  const std::string problem = topologyProblem([&] { checkClosedOrientedSurface(4, open, "mesh.triangles"); });
  EXPECT_NE(problem.find("open: 3 boundary edges"), std::string::npos) << problem;
}

TEST(MeshTopology, InconsistentOrientationIsRefused) {
  auto flipped = tetrahedron();
  std::swap(flipped[2][1], flipped[2][2]);
  const std::string problem = topologyProblem([&] { checkClosedOrientedSurface(4, flipped, "mesh.triangles"); });
  EXPECT_NE(problem.find("not consistently oriented: 3 edges"), std::string::npos) << problem;
}

TEST(MeshTopology, EdgesOfThreeTrianglesAndBadIndicesAreRefused) {
  // Two tetrahedra sharing the edge 0-1 and nothing else... plus a fin on that edge.
  auto crowded = tetrahedron();
  crowded.push_back({0, 1, 4});
  crowded.push_back({1, 0, 4});
  const std::string problem = topologyProblem([&] { checkClosedOrientedSurface(5, crowded, "mesh.triangles"); });
  EXPECT_NE(problem.find("more than two triangles"), std::string::npos) << problem;
  EXPECT_NE(topologyProblem([] { checkClosedOrientedSurface(3, tetrahedron(), "mesh.triangles"); }).find("vertex 3"),
            std::string::npos);
  EXPECT_NE(topologyProblem([] { checkClosedOrientedSurface(4, {{0, 1, 1}}, "mesh.triangles"); }).find("repeats"),
            std::string::npos);
  EXPECT_NE(topologyProblem([] { checkClosedOrientedSurface(4, {}, "mesh.triangles"); }).find("no triangles"),
            std::string::npos);
}
