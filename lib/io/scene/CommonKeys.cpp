// The keys of the common scene sections, registered in one place. Types, units, defaults and
// ranges written here are what the reader enforces, what `--help` prints and what
// docs/scenes.md documents (a test checks that every pattern appears there).

#include "integrators/ArkodeExplicit.hpp"
#include "integrators/IntegratorFactory.hpp"
#include "io/scene/SceneSchema.hpp"

namespace mfwave {

void SceneSchema::addTimeFunction(const std::string& prefix, const std::string& defaultNote, const std::string& doc) {
  using T = ValueType;
  add(prefix, T::Table).defaultsToNote(defaultNote).describedAs(doc);
  add(prefix + ".type", T::String)
      .required()
      .oneOf({"constant", "ramp", "triangle", "ricker", "tabulated"})
      .describedAs("kind of time function");
  add(prefix + ".value", T::Number).withUnit("-").defaultsTo("1.0").when("type = constant")
      .describedAs("the constant value");
  add(prefix + ".start", T::Number).withUnit("s").defaultsTo("0.0").when("type = ramp or triangle")
      .describedAs("time at which the ramp or pulse starts (0 before)");
  add(prefix + ".duration", T::Number).withUnit("s").required().positive().when("type = ramp")
      .describedAs("rise time of the ramp from 0 to amplitude, then held");
  add(prefix + ".rise", T::Number).withUnit("s").required().positive().when("type = triangle")
      .describedAs("time from start to the peak of the triangle");
  add(prefix + ".fall", T::Number).withUnit("s").defaultsToNote("= rise").positive().when("type = triangle")
      .describedAs("time from the peak back to 0");
  add(prefix + ".peak_frequency", T::Number).withUnit("1/s").required().positive().when("type = ricker")
      .describedAs("frequency of the Ricker spectrum's maximum");
  add(prefix + ".delay", T::Number).withUnit("s").defaultsToNote("1.5 / peak_frequency").when("type = ricker")
      .describedAs("time of the Ricker peak; the default starts the wavelet within 1e-8 of zero");
  add(prefix + ".amplitude", T::Number).withUnit("-").defaultsTo("1.0").when("type = ramp, triangle or ricker")
      .describedAs("peak value");
  add(prefix + ".times", T::NumberArray).withUnit("s").when("type = tabulated")
      .describedAs("sample times, strictly increasing, at least 2 (with values; or give file)");
  add(prefix + ".values", T::NumberArray).withUnit("-").when("type = tabulated")
      .describedAs("sample values, one per time (piecewise linear, held outside)");
  add(prefix + ".file", T::String).when("type = tabulated")
      .describedAs("CSV file of (time, value) rows, relative to the scene file's folder; instead of times/values");
}

SceneSchema SceneSchema::common() {
  using T = ValueType;
  SceneSchema s;

  s.add("scene", T::Table).required().describedAs("what the study is");
  s.add("scene.name", T::String).required().describedAs("name of the study; the default output folder is out/<name>");
  s.add("scene.description", T::String).describedAs("free text, copied to the run summary");
  s.add("scene.dimension", T::Integer).withUnit("-").required().between(1, 3)
      .describedAs("spatial dimension: 1, 2 or 3");

  s.add("geometry", T::Table).required().describedAs("the body: an axis-aligned box filled with a particle lattice");
  s.add("geometry.shape", T::String).required().oneOf({"line", "rectangle", "block"})
      .notSupportedYet({"bar", "plate", "ring", "half_space"})
      .describedAs("line (1-D), rectangle (2-D) or block (3-D), matching scene.dimension");
  s.add("geometry.lower", T::NumberArray).withUnit("m").required()
      .describedAs("lower corner of the box, one entry per axis");
  s.add("geometry.upper", T::NumberArray).withUnit("m").required()
      .describedAs("upper corner of the box, one entry per axis, each above lower");
  s.add("geometry.spacing", T::Number).withUnit("m").required().positive()
      .describedAs("lattice spacing; must divide every side of the box");
  s.add("geometry.ghost_layers", T::Integer).withUnit("-").defaultsTo("0").nonNegative()
      .describedAs("layers of ghost particles outside the ghost faces");
  s.add("geometry.ghost_faces", T::StringArray).defaultsToNote("all faces if ghost_layers > 0, else []")
      .describedAs("faces that get ghost layers: -x, +x, -y, +y, -z, +z (those of the dimension)");
  s.add("geometry.periodic", T::BooleanArray).defaultsToNote("all false")
      .describedAs("per axis: periodic (then no boundary may name a face of that axis)");

  s.add("material", T::Table).required().describedAs("isotropic linear elastic material");
  s.add("material.density", T::Number).withUnit("kg/m^3").required().positive().describedAs("mass density rho");
  s.add("material.lambda", T::Number).withUnit("Pa").defaultsToNote("with mu, or give youngs_modulus")
      .describedAs("first Lame constant (3 lambda + 2 mu > 0)");
  s.add("material.mu", T::Number).withUnit("Pa").defaultsToNote("with lambda").positive()
      .describedAs("shear modulus, second Lame constant");
  s.add("material.youngs_modulus", T::Number).withUnit("Pa").defaultsToNote("with poisson_ratio, or give lambda")
      .positive().describedAs("Young's modulus E");
  s.add("material.poisson_ratio", T::Number).withUnit("-").defaultsToNote("with youngs_modulus")
      .between(-1, 0.5, false, false).describedAs("Poisson's ratio nu");

  s.add("method", T::Table).required().describedAs("spatial discretisation; keys other than name are its options");
  s.add("method.name", T::String).required().oneOf({"finite_difference"})
      .describedAs("the method (methods and drivers register their names and options)");

  s.add("boundary", T::TableArray).describedAs("boundary conditions on box faces; faces not named are free");
  s.add("boundary[].faces", T::StringArray).required()
      .describedAs("faces of this condition: -x, +x, -y, +y, -z, +z; each face in at most one entry");
  s.add("boundary[].type", T::String).required().oneOf({"free", "fixed", "traction", "displacement", "transmitting", "symmetry"})
      .describedAs("kind of condition; symmetry: a mirror plane (zero normal displacement, zero tangential "
                   "traction), the box one side of a solid and load symmetric about it");
  s.add("boundary[].traction", T::NumberArray).withUnit("Pa").required().when("type = traction")
      .describedAs("traction vector, one entry per axis, scaled by time_function");
  s.add("boundary[].value", T::NumberArray).withUnit("m").defaultsToNote("zeros").when("type = displacement")
      .describedAs("prescribed displacement, one entry per axis, scaled by time_function");
  s.addTimeFunction("boundary[].time_function", "constant 1",
                    "time function scaling traction or value");
  s.at("boundary[].time_function").when("type = traction or displacement");

  s.add("load", T::TableArray)
      .describedAs("loads: point forces, body forces, surface patch tractions, moment tensors, tractions on a solid's surface");
  s.add("load[].type", T::String).required()
      .oneOf({"point_force", "body_force", "surface_patch", "moment_tensor", "surface_traction"})
      .describedAs("kind of load");
  s.add("load[].position", T::NumberArray).withUnit("m").required().when("type = point_force or moment_tensor")
      .describedAs("point of application, inside the geometry box");
  s.add("load[].moment", T::NumberArray).withUnit("N m").required().when("type = moment_tensor")
      .describedAs("the moment tensor M (body force -M grad delta), symmetric: xx, yy, xy in 2-D; xx, yy, zz, xy, xz, yz in "
                   "3-D; scaled by time_function");
  s.add("load[].surface", T::String).required().when("type = surface_traction")
      .describedAs("a named surface of the scene's solid: '<shape>.<surface>' (e.g. ground.plane, hole.surface, block.+z)");
  s.add("load[].radius", T::Number).withUnit("m").required().positive().when("type = surface_traction")
      .describedAs("the loaded part: the surface's points within this distance of centre");
  s.add("load[].pressure", T::Number).withUnit("Pa").when("type = surface_traction")
      .describedAs("traction along the inward normal (give pressure or traction), scaled by time_function");
  s.add("load[].direction", T::NumberArray).withUnit("-").required().when("type = point_force")
      .describedAs("direction of the force, non-zero; normalised");
  s.add("load[].amplitude", T::Number).withUnit("N").defaultsTo("1.0").when("type = point_force")
      .describedAs("magnitude of the force, scaled by time_function");
  s.add("load[].value", T::NumberArray).withUnit("N/m^3").required().when("type = body_force")
      .describedAs("body force per unit volume, one entry per axis, scaled by time_function");
  s.add("load[].face", T::String).required().when("type = surface_patch")
      .describedAs("box face carrying the patch: -x, +x, -y, +y, -z, +z (those of the dimension)");
  s.add("load[].centre", T::NumberArray).withUnit("m").required().when("type = surface_patch or surface_traction")
      .describedAs("centre of the rectangular patch, one entry per axis, on the face (surface_traction: of the loaded part)");
  s.add("load[].half_width", T::NumberArray).withUnit("m").required().when("type = surface_patch")
      .describedAs("half-widths of the patch along each axis, > 0 in the face, 0 along its normal");
  s.add("load[].traction", T::NumberArray).withUnit("Pa").when("type = surface_patch or surface_traction")
      .describedAs("traction vector on the patch, one entry per axis, scaled by time_function (required for "
                   "surface_patch; surface_traction: or pressure)");
  s.addTimeFunction("load[].time_function", "required but for body_force (constant 1)",
                    "time function scaling the load");

  s.add("integrator", T::Table).required().describedAs("time integration");
  s.add("integrator.name", T::String).defaultsTo("\"central_difference\"").oneOf(secondOrderIntegratorNames())
      .describedAs("second-order integrator");
  s.add("integrator.end_time", T::Number).withUnit("s").required().positive().describedAs("simulated time");
  s.add("integrator.time_step", T::Number).withUnit("s").positive()
      .describedAs("fixed time step (give time_step or cfl, not both)");
  s.add("integrator.cfl", T::Number).withUnit("-").defaultsToNote("0.5 unless time_step is given").positive()
      .describedAs("time step as a fraction of the method's stable step (finite_difference: dx / c_p)");
  s.add("integrator.newmark_beta", T::Number).withUnit("-").defaultsTo("0.25").between(0, 0.5)
      .when("name = newmark").describedAs("Newmark beta");
  s.add("integrator.newmark_gamma", T::Number).withUnit("-").defaultsTo("0.5").between(0, 1)
      .when("name = newmark").describedAs("Newmark gamma");
  s.add("integrator.arkode_table", T::String).defaultsTo("\"classic_rk4\"").oneOf(ArkodeExplicit::tableNames())
      .when("name = arkode").describedAs("ARKODE explicit Butcher table");
  s.add("integrator.arkode_adaptive", T::Boolean).defaultsTo("false").when("name = arkode")
      .describedAs("error-controlled steps (needs a table with an embedding)");
  s.add("integrator.arkode_relative_tolerance", T::Number).withUnit("-").defaultsTo("1e-06").positive()
      .when("name = arkode").describedAs("relative tolerance of adaptive steps");
  s.add("integrator.arkode_absolute_tolerance", T::Number).withUnit("-").defaultsTo("1e-09").nonNegative()
      .when("name = arkode").describedAs("absolute tolerance of adaptive steps");

  s.add("probe", T::TableArray).describedAs("time series of one component at one particle");
  s.add("probe[].name", T::String).required().describedAs("unique probe name (CSV column)");
  s.add("probe[].position", T::NumberArray).withUnit("m").defaultsToNote("position or particle")
      .describedAs("point inside the box; the nearest particle is recorded");
  s.add("probe[].particle", T::Integer).withUnit("-").defaultsToNote("position or particle").nonNegative()
      .describedAs("particle index (lattice order, x fastest)");
  s.add("probe[].quantity", T::String).defaultsTo("\"velocity\"").oneOf({"displacement", "velocity"})
      .describedAs("recorded field");
  s.add("probe[].component", T::String).required().oneOf({"x", "y", "z"})
      .describedAs("recorded component (valid for the dimension)");

  s.add("output", T::Table).describedAs("what is written");
  s.add("output.folder", T::String).defaultsToNote("\"out/<scene.name>\"").describedAs("output folder");
  s.add("output.every", T::Integer).withUnit("-").defaultsTo("10").atLeast(1)
      .describedAs("steps between VTK / PNG frames");
  s.add("output.vtk", T::Boolean).defaultsTo("false").describedAs("write VTK frames and a .pvd collection");
  s.add("output.png", T::Boolean).defaultsTo("false")
      .describedAs("write PNG frames every `every` steps (with or without vtk)");
  s.add("output.png_field", T::String).defaultsTo("\"velocity\"").oneOf({"displacement", "velocity"})
      .describedAs("field coloured in PNG frames");
  s.add("output.png_component", T::String).defaultsTo("\"magnitude\"").oneOf({"x", "y", "z", "magnitude"})
      .describedAs("component coloured in PNG frames (valid for the dimension)");
  s.add("output.png_point_size", T::Number).withUnit("px").defaultsTo("6.0").positive()
      .describedAs("particle size in PNG frames");
  s.add("output.png_width", T::Integer).withUnit("px").defaultsTo("1024").between(1, 16384).describedAs("PNG width");
  s.add("output.png_height", T::Integer).withUnit("px").defaultsTo("768").between(1, 16384).describedAs("PNG height");
  s.add("output.probe_every", T::Integer).withUnit("-").defaultsTo("1").atLeast(1)
      .describedAs("steps between probe samples");
  s.add("output.energy", T::Boolean).defaultsTo("true").describedAs("record the energy ledger");
  s.add("output.checkpoint_every", T::Integer).withUnit("-").defaultsTo("0").between(0, 1000000000000LL)
      .describedAs("steps between checkpoints in the output folder (0: none; --checkpoint-every overrides)");
  s.add("output.checkpoint_seconds", T::Number).withUnit("s").defaultsTo("0.0").between(0, 1e9)
      .describedAs("wall-clock seconds between checkpoints (0: none; --checkpoint-every overrides)");

  s.add("stability", T::Table).describedAs("stops a run that blows up");
  s.add("stability.growth_factor", T::Number).withUnit("-").defaultsTo("1000.0").above(1)
      .describedAs("stop at growth by this factor: of a grid-scale oscillation within `window` observations, or, after every load ended, of both displacement and velocity");
  s.add("stability.window", T::Integer).withUnit("-").defaultsTo("50").atLeast(1)
      .describedAs("observations over which growth is measured");
  s.add("stability.absolute_limit", T::Number).withUnit("m, m/s").defaultsTo("inf").positive().allowInfinity()
      .describedAs("stop at once when the largest displacement or velocity exceeds this");
  s.add("stability.energy_growth_factor", T::Number).withUnit("-").defaultsTo("100.0").above(1)
      .describedAs("linear systems: stop when kinetic + |strain| energy exceeds this multiple of its minimum after every load ended");
  s.add("stability.energy_balance_limit", T::Number).withUnit("-").defaultsTo("1.0").nonNegative()
      .describedAs("linear systems: stop when the energy balance moves by this multiple of the largest energy (0: off)");
  s.add("stability.allow_growth", T::Boolean).defaultsTo("false")
      .describedAs("run on through growth after the loads (the energy's or the monitor's) to show a blow-up on purpose; the summary reports it");
  return s;
}

}  // namespace mfwave
