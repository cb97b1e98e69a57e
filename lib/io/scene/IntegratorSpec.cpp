#include "io/scene/IntegratorSpec.hpp"

#include "integrators/FirstOrderIntegratorFactory.hpp"
#include "core/Error.hpp"
#include "io/scene/Format.hpp"

#include <cmath>
#include <stdexcept>

namespace mfwave {

IntegratorSpec readIntegrator(SceneReader& reader) {
  reader.table("integrator", true);
  IntegratorSpec s;
  s.name = reader.string("integrator.name");
  try {
    s.kind = integratorKind(s.name);
  } catch (const InputError& e) {
    reader.fail("integrator.name", scene::problemOf(e));
  }
  s.endTime = reader.number("integrator.end_time");
  if (reader.has("integrator.time_step") && reader.has("integrator.cfl"))
    reader.fail("integrator.cfl", "cannot be combined with time_step: give time_step (a fixed step) or cfl "
                                  "(a fraction of the stable step), not both");
  if (reader.has("integrator.time_step")) {
    s.timeStep = reader.number("integrator.time_step");
    const Real steps = s.endTime / *s.timeStep;
    const std::string tooMany = tooManySteps(steps, "end_time = " + scene::formatNumber(s.endTime) +
                                                        " at a step of " + scene::formatNumber(*s.timeStep));
    if (!tooMany.empty()) reader.fail("integrator.time_step", tooMany);
    if (std::abs(steps - std::round(steps)) > 1e-8 * std::max(Real(1), steps) || std::round(steps) < 1)
      reader.fail("integrator.time_step", scene::formatNumber(*s.timeStep) + " does not divide end_time = " +
                                              scene::formatNumber(s.endTime) + " into whole steps");
    s.cfl = 0;
  } else {
    s.cfl = reader.number("integrator.cfl", usesFirstOrderIntegrators(reader.schema()) ? 1.0 : 0.5);
  }

  const auto onlyWith = [&](const char* key, const std::string& integrator) {
    const std::string path = std::string("integrator.") + key;
    if (s.name != integrator && reader.has(path))
      reader.fail(path, "only allowed with name = \"" + integrator + "\" (name is \"" + s.name + "\")");
    return s.name == integrator;
  };
  const bool newmarkBeta = onlyWith("newmark_beta", "newmark");
  const bool newmarkGamma = onlyWith("newmark_gamma", "newmark");
  if (newmarkBeta && newmarkGamma) {
    s.options.newmarkBeta = reader.number("integrator.newmark_beta");
    s.options.newmarkGamma = reader.number("integrator.newmark_gamma");
  }
  bool arkode = true;
  for (const char* key : {"arkode_table", "arkode_adaptive", "arkode_relative_tolerance", "arkode_absolute_tolerance"})
    arkode = onlyWith(key, "arkode") && arkode;
  if (arkode) {
    ArkodeOptions& a = s.options.arkode;
    a.table = reader.string("integrator.arkode_table");
    a.adaptive = reader.boolean("integrator.arkode_adaptive");
    a.relativeTolerance = reader.number("integrator.arkode_relative_tolerance");
    a.absoluteTolerance = reader.number("integrator.arkode_absolute_tolerance");
    try {
      ArkodeExplicit check(a);  // the table, its embedding for adaptive runs, the tolerances
    } catch (const InputError& e) {
      const std::string key = e.key() == "integrator.table"                ? "integrator.arkode_table"
                              : e.key() == "integrator.relative_tolerance" ? "integrator.arkode_relative_tolerance"
                              : e.key() == "integrator.absolute_tolerance" ? "integrator.arkode_absolute_tolerance"
                                                                           : "integrator.name";
      reader.fail(key, scene::problemOf(e));
    }
  }
  return s;
}

void useFirstOrderIntegrators(SceneSchema& schema) {
  schema.at("integrator.name").oneOf(firstOrderIntegratorNames()).defaultsTo("\"leapfrog\"")
      .describedAs("first-order integrator (drivers of first-order systems)");
  schema.at("integrator.cfl").defaultsToNote("1.0 unless time_step is given")
      .describedAs("time step as a fraction of the method's own step criteria, evaluated before every step");
}

bool usesFirstOrderIntegrators(const SceneSchema& schema) {
  const KeySpec* name = schema.find("integrator.name");
  return name && name->choices == firstOrderIntegratorNames();
}

IntegratorSpec readFirstOrderIntegrator(SceneReader& reader) {
  if (!usesFirstOrderIntegrators(reader.schema()))
    throw std::logic_error("readFirstOrderIntegrator: the schema offers second-order integrators; call "
                           "useFirstOrderIntegrators(schema) before loading the scene");
  return readIntegrator(reader);
}

}  // namespace mfwave
