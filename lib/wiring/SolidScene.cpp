#include "wiring/SolidScene.hpp"

#include "core/Error.hpp"
#include "geometry/Annulus.hpp"
#include "geometry/Ball.hpp"
#include "geometry/BoxSolid.hpp"
#include "geometry/Cylinder.hpp"
#include "geometry/ExtrudedPolygon.hpp"
#include "geometry/HalfSpace.hpp"
#include "geometry/Polygon.hpp"
#include "geometry/SolidExpression.hpp"
#include "geometry/SurfaceMeshFile.hpp"
#include "io/scene/Format.hpp"
#include "io/scene/ScenePath.hpp"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>

namespace mfwave {

void addSolidKeys(SceneSchema& s) {
  using T = ValueType;
  s.add("geometry.solid", T::String).defaultsTo("\"box\"")
      .describedAs("the solid: a CSG expression over [[shape]] names within the box ('box'): + union, - difference, "
                   "& intersection, parentheses");
  s.add("geometry.region_overlap", T::String).defaultsTo("\"error\"").oneOf({"error", "last"})
      .describedAs("where two [[region]] entries overlap: refuse (error) or let the later one win (last)");
  s.add("shape", T::TableArray).describedAs("named shapes the solid and the regions are made of");
  s.add("shape[].name", T::String).required().describedAs("the shape's name in expressions and surface names");
  s.add("shape[].type", T::String).required()
      .oneOf({"box", "half_space", "ball", "annulus", "cylinder", "polygon", "extruded_polygon", "mesh"})
      .describedAs("kind of shape (ball is a disc in 2-D, annulus a spherical shell in 3-D; cylinder, extruded_polygon "
                   "and mesh are 3-D; polygon 2-D)");
  s.add("shape[].lower", T::NumberArray).withUnit("m").required().when("type = box").describedAs("lower corner");
  s.add("shape[].upper", T::NumberArray).withUnit("m").required().when("type = box").describedAs("upper corner");
  s.add("shape[].point", T::NumberArray).withUnit("m").required().when("type = half_space")
      .describedAs("a point of the bounding plane (line in 2-D)");
  s.add("shape[].normal", T::NumberArray).withUnit("-").required().when("type = half_space")
      .describedAs("the plane's normal, pointing out of the half-space");
  s.add("shape[].centre", T::NumberArray).withUnit("m").required().when("type = ball or annulus").describedAs("centre");
  s.add("shape[].inner_radius", T::Number).withUnit("m").required().positive().when("type = annulus")
      .describedAs("an annulus's inner radius");
  s.add("shape[].outer_radius", T::Number).withUnit("m").required().positive().when("type = annulus")
      .describedAs("an annulus's outer radius (above inner_radius)");
  s.add("shape[].radius", T::Number).withUnit("m").required().positive().when("type = ball or cylinder")
      .describedAs("radius");
  s.add("shape[].start", T::NumberArray).withUnit("m").required().when("type = cylinder")
      .describedAs("centre of the bottom cap");
  s.add("shape[].end", T::NumberArray).withUnit("m").required().when("type = cylinder").describedAs("centre of the top cap");
  s.add("shape[].vertices", T::NumberArray).withUnit("m").required().when("type = polygon or extruded_polygon")
      .describedAs("the polygon's vertices in order, x0, y0, x1, y1, ... (at least 3)");
  s.add("shape[].z_range", T::NumberArray).withUnit("m").required().when("type = extruded_polygon")
      .describedAs("[z0, z1]: the extrusion's bottom and top");
  s.add("shape[].file", T::String).required().when("type = mesh")
      .describedAs("closed triangle surface (STL, OBJ or VTP), relative to the scene file's folder");
  s.add("region", T::TableArray).describedAs("materials by region: each an expression over shapes and a material");
  s.add("region[].name", T::String).required().describedAs("the region's name");
  s.add("region[].solid", T::String).required().describedAs("the region: a CSG expression over [[shape]] names");
  s.add("region[].density", T::Number).withUnit("kg/m^3").defaultsToNote("[material]'s").positive()
      .describedAs("rho (give density, lambda and mu, or none: the region then has [material]'s)");
  s.add("region[].lambda", T::Number).withUnit("Pa").defaultsToNote("[material]'s").nonNegative()
      .describedAs("Lame's first parameter");
  s.add("region[].mu", T::Number).withUnit("Pa").defaultsToNote("[material]'s").positive().describedAs("shear modulus");
  s.add("region[].initial_velocity", T::NumberArray).withUnit("m/s").defaultsToNote("at rest")
      .describedAs("velocity of the region's material at t = 0, one entry per axis");
  s.add("region[].initial_displacement", T::NumberArray).withUnit("m").defaultsToNote("none")
      .describedAs("displacement of the region's material at t = 0, one entry per axis");
  s.add("crack", T::TableArray)
      .describedAs("cracks: surfaces of zero thickness across which the material does not interact (the particle "
                   "methods cut every pair whose segment crosses one)");
  s.add("crack[].from", T::NumberArray).withUnit("m").describedAs("2-D: one end of the crack's segment");
  s.add("crack[].to", T::NumberArray).withUnit("m").describedAs("2-D: the other end");
  s.add("crack[].corner", T::NumberArray).withUnit("m").describedAs("3-D: a corner of the crack's rectangle");
  s.add("crack[].edge1", T::NumberArray).withUnit("m").describedAs("3-D: the rectangle's first edge from the corner");
  s.add("crack[].edge2", T::NumberArray).withUnit("m").describedAs("3-D: its second edge from the corner");
}

namespace {

bool validName(const std::string& name) {
  if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0])) != 0) return false;
  for (const char c : name)
    if (std::isalnum(static_cast<unsigned char>(c)) == 0 && c != '_') return false;
  return true;
}

template <int D>
SolidPtr<D> readShape(SceneReader& reader, std::size_t i, const std::string& name, const std::string& type) {
  const std::string entry = scene::indexPath("shape", i);
  const auto key = [&](const char* k) { return scene::childPath(entry, k); };
  const auto d = static_cast<std::size_t>(D);
  try {
    if (type == "box") return std::make_shared<BoxSolid<D>>(scene::vectorOf<D>(reader.numbers(key("lower"), d)),
                                                             scene::vectorOf<D>(reader.numbers(key("upper"), d)), name);
    if (type == "half_space")
      return std::make_shared<HalfSpace<D>>(scene::vectorOf<D>(reader.numbers(key("point"), d)), scene::vectorOf<D>(reader.numbers(key("normal"), d)),
                                            name);
    if (type == "ball")
      return std::make_shared<Ball<D>>(scene::vectorOf<D>(reader.numbers(key("centre"), d)), reader.number(key("radius")), name);
    if (type == "annulus")
      return std::make_shared<Annulus<D>>(scene::vectorOf<D>(reader.numbers(key("centre"), d)), reader.number(key("inner_radius")),
                                          reader.number(key("outer_radius")), name);
    if constexpr (D == 2) {
      if (type == "polygon") {
        const std::vector<Real> v = reader.numbers(key("vertices"));
        if (v.size() % 2 != 0) reader.fail(key("vertices"), "needs x, y pairs (an even count), got " + std::to_string(v.size()));
        std::vector<Vec2> vertices;
        for (std::size_t k = 0; k + 1 < v.size(); k += 2) vertices.emplace_back(v[k], v[k + 1]);
        return std::make_shared<Polygon>(std::move(vertices), name);
      }
    }
    if constexpr (D == 3) {
      if (type == "cylinder")
        return std::make_shared<Cylinder>(scene::vectorOf<3>(reader.numbers(key("start"), 3)), scene::vectorOf<3>(reader.numbers(key("end"), 3)),
                                          reader.number(key("radius")), name);
      if (type == "extruded_polygon") {
        const std::vector<Real> v = reader.numbers(key("vertices"));
        if (v.size() % 2 != 0) reader.fail(key("vertices"), "needs x, y pairs (an even count), got " + std::to_string(v.size()));
        std::vector<Vec2> vertices;
        for (std::size_t k = 0; k + 1 < v.size(); k += 2) vertices.emplace_back(v[k], v[k + 1]);
        const std::vector<Real> z = reader.numbers(key("z_range"), 2);
        return std::make_shared<ExtrudedPolygon>(std::move(vertices), z[0], z[1], name);
      }
      if (type == "mesh") {
        namespace fs = std::filesystem;
        fs::path file(reader.string(key("file")));
        if (file.is_relative()) file = fs::path(reader.baseDirectory()) / file;
        return std::make_shared<TriangleMesh>(readSurfaceMesh(fs::absolute(file).lexically_normal().string(), name));
      }
    }
  } catch (const InputError& e) {
    reader.fail(key("type"), e.what());
  }
  reader.fail(key("type"), "'" + type + "' is not a shape of a " + std::to_string(D) + "-D scene");
}

// The lattice nodes of the scene's box (what the checks sample).
template <int D>
void forEachNode(const GeometrySpec& g, const std::function<void(const Vec<D>&)>& visit) {
  std::array<Index, D> n{};
  Index count = 1;
  for (int a = 0; a < D; ++a) {
    n[static_cast<std::size_t>(a)] = g.intervals[static_cast<std::size_t>(a)] + 1;
    count *= n[static_cast<std::size_t>(a)];
  }
  for (Index p = 0; p < count; ++p) {
    Index rest = p;
    Vec<D> x;
    for (int a = 0; a < D; ++a) {
      const auto k = static_cast<std::size_t>(a);
      x[a] = g.lower[k] + static_cast<Real>(rest % n[k]) * g.spacing;
      rest /= n[k];
    }
    visit(x);
  }
}

}  // namespace

template <int D>
int SceneSolid<D>::regionAt(const Vec<D>& x) const {
  for (int r = static_cast<int>(regions.size()) - 1; r >= 0; --r)
    if (regions[static_cast<std::size_t>(r)]->signedDistance(x) <= 0) return r;
  return -1;
}

template <int D>
int SceneSolid<D>::materialAt(const Vec<D>& x) const {
  return regionAt(x) + 1;
}

template <int D>
Real SceneSolid<D>::interfaceDistance(const Vec<D>& x) const {
  Real d = std::numeric_limits<Real>::infinity();
  for (const SolidPtr<D>& r : regions) d = std::min(d, std::abs(r->signedDistance(x)));
  return d;
}

template <int D>
SceneSolid<D> readSceneSolid(SceneReader& reader, const Scene& scene) {
  const GeometrySpec& g = scene.geometry;
  SceneSolid<D> out;
  out.box = std::make_shared<BoxSolid<D>>(scene::vectorOf<D>(g.lower), scene::vectorOf<D>(g.upper), "box");
  std::map<std::string, SolidPtr<D>> shapes{{"box", out.box}};
  std::vector<std::string> names{"box"};
  const std::size_t count = reader.count("shape");
  for (std::size_t i = 0; i < count; ++i) {
    const std::string key = scene::childPath(scene::indexPath("shape", i), "name");
    const std::string name = reader.string(key);
    if (!validName(name)) reader.fail(key, "'" + name + "' is not a name (letters, digits and _, not starting with a digit)");
    if (shapes.count(name) != 0)
      reader.fail(key, name == "box" ? "'box' is the scene's box; give the shape another name" : "'" + name + "' names two shapes");
    SolidPtr<D> shape = readShape<D>(reader, i, name, reader.string(scene::childPath(scene::indexPath("shape", i), "type")));
    // a shape that no node of the box reaches is a mistake (a region outside the box)
    bool meets = false;
    forEachNode<D>(g, [&](const Vec<D>& x) { meets = meets || shape->signedDistance(x) <= g.spacing / 2; });
    if (!meets)
      reader.fail(scene::childPath(scene::indexPath("shape", i), "type"),
                  "shape '" + name + "' lies outside the geometry box " + g.describeBox());
    shapes[name] = shape;
    names.push_back(name);
  }
  const std::function<SolidPtr<D>(const std::string&)> lookup = [&shapes](const std::string& n) -> SolidPtr<D> {
    const auto it = shapes.find(n);
    return it == shapes.end() ? nullptr : it->second;
  };
  const std::string expression = reader.string("geometry.solid");
  try {
    out.expression = parseSolidExpression<D>(expression, lookup, names, "geometry.solid");
  } catch (const InputError& e) {
    reader.fail("geometry.solid", e.problem());
  }
  out.solid = intersect<D>(out.box, out.expression);
  {
    Vec<D> far = Vec<D>::Zero();
    for (int a = 0; a < D; ++a) far[a] = 1e6 * (std::abs(g.upper[static_cast<std::size_t>(a)]) + std::abs(g.lower[static_cast<std::size_t>(a)]) + 1);
    const SolidPtr<D> everywhere = std::make_shared<BoxSolid<D>>(-far, far, "box");
    const std::function<SolidPtr<D>(const std::string&)> unboundedLookup = [&](const std::string& n) -> SolidPtr<D> {
      return n == "box" ? everywhere : lookup(n);
    };
    out.unbounded = parseSolidExpression<D>(expression, unboundedLookup, names, "geometry.solid");
  }
  Index inside = 0;
  forEachNode<D>(g, [&](const Vec<D>& x) { inside += out.solid->signedDistance(x) <= 0 ? 1 : 0; });
  out.latticeFraction = static_cast<Real>(inside) / static_cast<Real>(g.particleCount());
  if (inside == 0)
    reader.fail("geometry.solid", "'" + expression + "' is empty within the box " + g.describeBox() +
                                      " (no lattice node at spacing " + scene::formatNumber(g.spacing) + " inside it)");

  out.materials.push_back(scene.material.material());
  out.lastRegionWins = reader.string("geometry.region_overlap") == "last";
  const std::size_t regionCount = reader.count("region");
  for (std::size_t i = 0; i < regionCount; ++i) {
    const std::string entry = scene::indexPath("region", i);
    const auto key = [&](const char* k) { return scene::childPath(entry, k); };
    out.regionNames.push_back(reader.string(key("name")));
    SolidPtr<D> region;
    try {
      region = parseSolidExpression<D>(reader.string(key("solid")), lookup, names, key("solid"));
    } catch (const InputError& e) {
      reader.fail(key("solid"), e.problem());
    }
    bool meets = false;
    forEachNode<D>(g, [&](const Vec<D>& x) { meets = meets || (region->signedDistance(x) <= 0 && out.solid->signedDistance(x) <= 0); });
    if (!meets) reader.fail(key("solid"), "region '" + out.regionNames.back() + "' holds no point of the solid at spacing " +
                                              scene::formatNumber(g.spacing) + " (outside the box or the solid)");
    out.regions.push_back(region);
    const int given = (reader.has(key("density")) ? 1 : 0) + (reader.has(key("lambda")) ? 1 : 0) + (reader.has(key("mu")) ? 1 : 0);
    if (given == 0) {
      out.materials.push_back(scene.material.material());  // a region for its initial velocity alone
    } else {
      for (const char* k : {"density", "lambda", "mu"})
        if (!reader.has(key(k)))
          reader.fail(key(k), "is missing: a region's material is density, lambda and mu together (or none of them)");
      out.materials.push_back(
          Material::fromLame(reader.number(key("lambda")), reader.number(key("mu")), reader.number(key("density"))));
    }
    out.initialVelocity.push_back(reader.has(key("initial_velocity")) ? reader.numbers(key("initial_velocity"), D)
                                                                      : std::vector<Real>{});
    out.initialDisplacement.push_back(reader.has(key("initial_displacement"))
                                          ? reader.numbers(key("initial_displacement"), D)
                                          : std::vector<Real>{});
  }
  // cracks: a segment (2-D) or a rectangle (3-D) with its points in the box
  for (std::size_t i = 0; i < reader.count("crack"); ++i) {
    const auto key = [i](const char* k) { return scene::childPath(scene::indexPath("crack", i), k); };
    std::vector<Vec<D>> points;
    const char* first = D == 2 ? "from" : "corner";
    try {
      if constexpr (D == 2) {
        const Vec<D> a = scene::vectorOf<D>(reader.numbers(key("from"), D)), b = scene::vectorOf<D>(reader.numbers(key("to"), D));
        out.cracks.add(Crack<2>(a, b));
        points = {a, b};
      } else {
        const Vec<D> c = scene::vectorOf<D>(reader.numbers(key("corner"), D));
        const Vec<D> e1 = scene::vectorOf<D>(reader.numbers(key("edge1"), D)), e2 = scene::vectorOf<D>(reader.numbers(key("edge2"), D));
        out.cracks.add(Crack<3>::rectangle(c, e1, e2));
        points = {c, Vec<D>(c + e1), Vec<D>(c + e2), Vec<D>(c + e1 + e2)};
      }
    } catch (const InputError& e) {
      reader.fail(key(first), e.problem());
    }
    for (const Vec<D>& x : points)
      if (out.box->signedDistance(x) > 1e-9 * g.spacing)
        reader.fail(key(first), "the crack reaches " + scene::formatPoint(std::vector<Real>(x.data(), x.data() + D)) +
                                    ", outside the geometry box " + g.describeBox());
  }
  if (!out.lastRegionWins && out.regions.size() > 1) {
    forEachNode<D>(g, [&](const Vec<D>& x) {
      if (out.solid->signedDistance(x) > 0) return;
      int first = -1;
      for (std::size_t r = 0; r < out.regions.size(); ++r) {
        if (out.regions[r]->signedDistance(x) >= 0) continue;  // strictly inside: a shared surface is no overlap
        if (first >= 0)
          reader.fail(scene::childPath(scene::indexPath("region", r), "solid"),
                      "regions '" + out.regionNames[static_cast<std::size_t>(first)] + "' and '" + out.regionNames[r] +
                          "' overlap at " + scene::formatPoint(std::vector<Real>(x.data(), x.data() + D)) +
                          "; make them disjoint or set geometry.region_overlap = \"last\" (the later region wins)");
        first = static_cast<int>(r);
      }
    });
  }
  return out;
}

template struct SceneSolid<2>;
template struct SceneSolid<3>;
template SceneSolid<2> readSceneSolid<2>(SceneReader&, const Scene&);
template SceneSolid<3> readSceneSolid<3>(SceneReader&, const Scene&);

}  // namespace mfwave
