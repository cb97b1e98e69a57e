#include "io/scene/GeometrySpec.hpp"

#include "io/scene/Faces.hpp"
#include "io/scene/Format.hpp"
#include "io/scene/ScenePath.hpp"
#include "particles/Lattice.hpp"

#include <cmath>
#include <sstream>

namespace mfwave {
namespace {

template <int D>
std::vector<Index> intervalsOf(const std::vector<Real>& lower, const std::vector<Real>& upper, Real dx) {
  const auto n = latticeIntervals<D>(Eigen::Map<const Vec<D>>(lower.data()), Eigen::Map<const Vec<D>>(upper.data()), dx);
  return std::vector<Index>(n.begin(), n.end());
}

// latticeIntervals prints numbers with 17 digits ("0.29999999999999999"): show the shortest form.
std::string shortenNumbers(std::string problem, const GeometrySpec& g) {
  std::vector<Real> numbers{g.spacing};
  for (std::size_t a = 0; a < g.lower.size(); ++a) numbers.push_back(g.upper[a] - g.lower[a]);
  for (const Real x : numbers) {
    std::ostringstream long17;
    long17.precision(17);
    long17 << x;
    for (auto at = problem.find(long17.str()); at != std::string::npos; at = problem.find(long17.str(), at + 1))
      problem.replace(at, long17.str().size(), scene::formatNumber(x));
  }
  return problem;
}

const char* shapeOfDimension(int dimension) {
  static const char* const shapes[] = {"line", "rectangle", "block"};
  return shapes[dimension - 1];
}

}  // namespace

Index GeometrySpec::particleCount() const {
  Index count = 1;
  for (const Index n : intervals) count *= n + 1;
  return count;
}

bool GeometrySpec::contains(const std::vector<Real>& x) const {
  for (int a = 0; a < dimension; ++a) {
    const auto i = static_cast<std::size_t>(a);
    const Real tolerance = 1e-9 * (upper[i] - lower[i]);
    if (!(x[i] >= lower[i] - tolerance && x[i] <= upper[i] + tolerance)) return false;
  }
  return true;
}

std::string GeometrySpec::describeBox() const {
  std::string box;
  for (std::size_t a = 0; a < lower.size(); ++a)
    box += (a ? " x [" : "[") + scene::formatNumber(lower[a]) + ", " + scene::formatNumber(upper[a]) + "]";
  return box;
}

GeometrySpec GeometrySpec::withLattice(const std::vector<Real>& newLower, const std::vector<Real>& newUpper,
                                       Real newSpacing) const {
  GeometrySpec g = *this;
  g.lower = newLower;
  g.upper = newUpper;
  g.spacing = newSpacing;
  if (g.lower.size() != static_cast<std::size_t>(dimension) || g.upper.size() != g.lower.size())
    throw InputError("geometry.lower", "needs one entry per axis");
  try {
    g.intervals = dimension == 1   ? intervalsOf<1>(g.lower, g.upper, g.spacing)
                  : dimension == 2 ? intervalsOf<2>(g.lower, g.upper, g.spacing)
                                   : intervalsOf<3>(g.lower, g.upper, g.spacing);
  } catch (const InputError& e) {
    throw InputError(e.key() == "spacing" ? "geometry.spacing" : "geometry.upper",
                     shortenNumbers(scene::problemOf(e), g));
  }
  return g;
}

GeometrySpec readGeometry(SceneReader& reader, int dimension) {
  reader.table("geometry", true);
  GeometrySpec g;
  g.dimension = dimension;
  const auto d = static_cast<std::size_t>(dimension);
  g.shape = reader.string("geometry.shape");
  const std::string expected = shapeOfDimension(dimension);
  if (g.shape != expected)
    reader.fail("geometry.shape", "'" + g.shape + "' does not match scene.dimension = " + std::to_string(dimension) +
                                      " (a " + std::to_string(dimension) + "-D scene is a '" + expected + "')");
  g.lower = reader.numbers("geometry.lower", d);
  g.upper = reader.numbers("geometry.upper", d);
  for (std::size_t a = 0; a < d; ++a)
    if (!(g.upper[a] > g.lower[a]))
      reader.fail(scene::indexPath("geometry.upper", a),
                  "must be greater than lower[" + std::to_string(a) + "] = " + scene::formatNumber(g.lower[a]) +
                      ", got " + scene::formatNumber(g.upper[a]));
  g.spacing = reader.number("geometry.spacing");
  try {
    g.intervals = dimension == 1   ? intervalsOf<1>(g.lower, g.upper, g.spacing)
                  : dimension == 2 ? intervalsOf<2>(g.lower, g.upper, g.spacing)
                                   : intervalsOf<3>(g.lower, g.upper, g.spacing);
  } catch (const InputError& e) {
    reader.fail(e.key() == "spacing" ? "geometry.spacing" : "geometry.upper", shortenNumbers(scene::problemOf(e), g));
  }
  const std::int64_t layers = reader.integer("geometry.ghost_layers");
  if (layers > 1000) reader.fail("geometry.ghost_layers", "is too large, got " + std::to_string(layers));
  g.ghostLayers = static_cast<int>(layers);
  const std::vector<std::string> ghostDefault = g.ghostLayers > 0 ? faceNames(dimension) : std::vector<std::string>{};
  g.ghostFaces = faceMaskOf(readFaces(reader, "geometry.ghost_faces", dimension, &ghostDefault));
  g.periodic = reader.booleans("geometry.periodic", d, std::vector<bool>(d, false));
  return g;
}

}  // namespace mfwave
