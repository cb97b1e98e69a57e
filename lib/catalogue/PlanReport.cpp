#include "catalogue/PlanReport.hpp"

#include "io/scene/Faces.hpp"
#include "particles/BoxFace.hpp"
#include "io/scene/Format.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace mfwave {
namespace {

using scene::formatNumber;

std::string significant(double x, int digits = 3) {
  if (!std::isfinite(x)) return std::isnan(x) ? "unknown" : "inf";
  std::ostringstream s;
  s << std::setprecision(digits) << x;
  return s.str();
}

std::string mebibytes(double bytes) { return significant(bytes / 1048576.0) + " MiB"; }

std::string seconds(double s) {
  if (!std::isfinite(s)) return "unknown";
  if (s < 120) return significant(s) + " s";
  if (s < 7200) return significant(s / 60) + " min";
  return significant(s / 3600) + " h";
}

std::string faces(std::uint8_t mask, int dimension) {
  std::vector<std::string> names;
  for (int f = 0; f < 2 * dimension; ++f)
    if (mask & faceBit(f)) names.push_back(faceName(f));
  return scene::joinNames(names);
}

// The method's own [method] keys, as its catalogue schema declares them (method.name left out).
std::vector<KeySpec> methodOptions(const MethodEntry& m) {
  const SceneSchema schema = catalogueSchema(m);
  std::vector<KeySpec> options;
  for (const KeySpec& k : schema.keys())
    if (k.path.rfind("method.", 0) == 0 && k.path != "method.name") options.push_back(k);
  return options;
}

std::string optionList(const MethodEntry& m) {
  std::ostringstream out;
  for (const KeySpec& k : methodOptions(m)) {
    out << "      " << std::left << std::setw(40) << k.path << ' ' << std::setw(8) << typeName(k.type) << ' '
        << std::setw(16) << k.defaultText() << ' ' << k.doc << '\n';
  }
  return out.str();
}

template <typename T, typename F>
std::string names(const std::vector<T>& values, F name) {
  std::vector<std::string> out;
  for (const T& v : values) out.push_back(name(v));
  return out.empty() ? std::string("none") : scene::joinNames(out);
}

}  // namespace

void printResolvedModel(std::ostream& out, const Scene& scene, const MethodChoice& choice, const Prediction& p) {
  const GeometrySpec& g = scene.geometry;
  const Material material = scene.material.material();
  out << "scene        " << scene.info.name << " (" << g.dimension << "-D)\n"
      << "geometry     " << g.shape << ' ' << g.describeBox() << ", spacing " << formatNumber(g.spacing) << " m, "
      << g.particleCount() << " particles"
      << (p.particles > g.particleCount() ? " and " + std::to_string(p.particles - g.particleCount()) + " ghosts" : "")
      << '\n'
      << "material     rho " << formatNumber(material.density()) << ", lambda " << formatNumber(material.lambda())
      << ", mu " << formatNumber(material.mu()) << "; c_p " << significant(material.pWaveSpeed(), 5) << ", c_s "
      << significant(material.sWaveSpeed(), 5) << " m/s\n";
  std::uint8_t named = 0;
  for (const BoundarySpec& b : scene.boundaries) {
    out << "boundary     " << faces(b.faceMask, g.dimension) << ": " << boundaryTypeName(b.type) << '\n';
    named |= b.faceMask;
  }
  const std::uint8_t all = allFaces(g.dimension);
  std::uint8_t periodic = 0;
  for (int a = 0; a < g.dimension; ++a)
    if (a < static_cast<int>(g.periodic.size()) && g.periodic[static_cast<std::size_t>(a)])
      periodic |= static_cast<std::uint8_t>(faceBit(2 * a) | faceBit(2 * a + 1));
  if (const std::uint8_t free = static_cast<std::uint8_t>(all & ~named & ~periodic))
    out << "boundary     " << faces(free, g.dimension) << ": free (not named)\n";
  for (const LoadSpec& l : scene.loads) {
    out << "load         " << loadTypeName(l.type);
    if (l.type == LoadType::PointForce) out << " at " << scene::formatPoint(l.position);
    if (l.type == LoadType::SurfacePatch)
      out << " on " << faceName(l.face) << " centred at " << scene::formatPoint(l.centre);
    out << ", " << l.timeFunction.describe() << '\n';
  }
  for (const ProbeSpec& probe : scene.probes)
    out << "probe        " << probe.name
        << (probe.position ? " at " + scene::formatPoint(*probe.position)
                           : " on particle " + std::to_string(probe.particle.value_or(0)))
        << '\n';
  out << "method       " << choice.label() << ": " << choice.method->title << '\n'
      << "integrator   " << scene.integrator.name << " to t = " << formatNumber(scene.integrator.endTime) << " s, "
      << (scene.integrator.timeStep ? "time_step " + formatNumber(*scene.integrator.timeStep) + " s"
                                    : "cfl " + formatNumber(scene.integrator.cfl) + " of the stable step")
      << '\n'
      << "step         " << significant(p.timeStep, 4) << " s x " << p.steps << " steps (stable step "
      << significant(p.stableStep, 4) << " s predicted from " << choice.method->stepRule << ")\n";
}

void printPrediction(std::ostream& out, const Prediction& p) {
  out << "method              " << p.method << " at spacing " << formatNumber(p.spacing) << " m\n"
      << "particles           " << p.particles << '\n'
      << "peak memory         " << mebibytes(p.memoryBytes) << '\n'
      << "stable step         " << significant(p.stableStep, 4) << " s\n"
      << "time step, steps    " << significant(p.timeStep, 4) << " s, " << p.steps << '\n'
      << "wall time           " << seconds(p.wallSeconds) << " on one core (set-up " << seconds(p.setupSeconds)
      << ")\n";
  if (p.hasSource)
    out << "dominant frequency  " << significant(p.frequency, 4) << " Hz from " << p.frequencySource << '\n'
        << "points / wavelength " << significant(p.pointsPerWavelength) << " (" << p.phaseWave << ")\n"
        << "phase error         " << significant(p.phaseError) << " (the row alone " << significant(p.spatialPhaseError)
        << ")\n";
  for (const std::string& n : p.notes) out << "note: " << n << '\n';
}

nlohmann::json predictionJson(const Prediction& p) {
  nlohmann::json j;
  const auto number = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); };
  j["method"] = p.method;
  j["spacing"] = p.spacing;
  j["particles"] = p.particles;
  j["memory_bytes"] = number(p.memoryBytes);
  j["stable_step"] = number(p.stableStep);
  j["time_step"] = number(p.timeStep);
  j["steps"] = p.steps;
  j["setup_seconds"] = number(p.setupSeconds);
  j["wall_seconds"] = number(p.wallSeconds);
  j["dominant_frequency"] = p.hasSource ? number(p.frequency) : nlohmann::json(nullptr);
  j["points_per_wavelength"] = p.hasSource ? number(p.pointsPerWavelength) : nlohmann::json(nullptr);
  j["phase_error"] = p.hasSource ? number(p.phaseError) : nlohmann::json(nullptr);
  j["spatial_phase_error"] = p.hasSource ? number(p.spatialPhaseError) : nlohmann::json(nullptr);
  j["growing_modes"] = p.growing;
  j["notes"] = p.notes;
  return j;
}

void printCatalogue(std::ostream& out) {
  for (const MethodEntry& m : methodCatalogue()) {
    const MethodSupport& s = m.supports;
    out << m.name << ": " << m.title << '\n'
        << "    " << m.summary << '\n';
    if (!m.variants.empty()) out << "    variants     " << scene::joinNames(m.variants) << " (method.variant)\n";
    out << "    dimensions   " << names(s.dimensions, [](int d) { return std::to_string(d) + "-D"; }) << '\n'
        << "    geometry     " << names(s.shapes, [](const std::string& x) { return x; })
        << (s.solidPrograms.empty() ? std::string()
                                    : "; solids of shapes in " + names(s.solidPrograms, [](const std::string& x) { return x; }))
        << '\n'
        << "    boundaries   " << names(s.boundaries, boundaryTypeName) << '\n'
        << "    loads        " << names(s.loads, loadTypeName) << '\n'
        << "    integrators  " << names(s.integrators, [](const std::string& x) { return x; }) << '\n'
        << "    stable step  " << m.stepRule << '\n'
        << "    programs     " << names(m.programs, [](const std::string& x) { return x; }) << '\n';
    const std::string options = optionList(m);
    out << "    options" << (options.empty() ? "      none\n" : ":\n" + options) << '\n';
  }
}

nlohmann::json catalogueJson() {
  nlohmann::json list = nlohmann::json::array();
  for (const MethodEntry& m : methodCatalogue()) {
    nlohmann::json e;
    e["name"] = m.name;
    e["title"] = m.title;
    e["variants"] = m.variants;
    e["dimensions"] = m.supports.dimensions;
    e["geometry"] = m.supports.shapes;
    e["solid_programs"] = m.supports.solidPrograms;
    std::vector<std::string> b, l;
    for (BoundaryType t : m.supports.boundaries) b.push_back(boundaryTypeName(t));
    for (LoadType t : m.supports.loads) l.push_back(loadTypeName(t));
    e["boundaries"] = b;
    e["loads"] = l;
    e["integrators"] = m.supports.integrators;
    e["stable_step"] = m.stepRule;
    e["programs"] = m.programs;
    nlohmann::json options = nlohmann::json::array();
    for (const KeySpec& k : methodOptions(m))
      options.push_back({{"key", k.path}, {"type", typeName(k.type)}, {"default", k.defaultText()}, {"doc", k.doc}});
    e["options"] = options;
    list.push_back(e);
  }
  return list;
}

}  // namespace mfwave
