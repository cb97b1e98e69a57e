#include "catalogue/MethodCatalogue.hpp"

#include "core/Error.hpp"
#include "integrators/FirstOrderIntegratorFactory.hpp"
#include "integrators/IntegratorFactory.hpp"
#include "io/scene/Format.hpp"
#include "io/scene/IntegratorSpec.hpp"
#include "study/UpdatedLagrangianSphSpec.hpp"
#include "study/VeryWeakSphSpec.hpp"

#include <algorithm>

namespace mfwave {
namespace {

using B = BoundaryType;
using L = LoadType;
using T = ValueType;

// The [method] keys of the methods whose keys no library registers yet (their studies declare them
// with study-specific defaults: the catalogue says so in each default's note).
void addCollocationOptions(SceneSchema& schema) {
  const std::string when = "name = reproducing_kernel";
  schema.add("method.order", T::Integer).withUnit("-").defaultsTo("2").between(1, 3).when(when)
      .describedAs("RK basis order m (2 or 3: collocation needs second derivatives)");
  schema.add("method.support_ratio", T::Number).withUnit("-")
      .defaultsToNote("2.5 (1-D, 2-D); 2.2 in 3-D, the widest support whose interior rows do not grow").positive()
      .when(when).describedAs("cubic B-spline support radius a / h (bar1d takes 3.3, the paper's)");
}

void addRadialBasisOptions(SceneSchema& schema) {
  const std::string when = "name = radial_basis";
  schema.add("method.basis", T::String).defaultsTo("\"inverse_multiquadric\"").when(when)
      .describedAs("radial basis function");
  schema.add("method.shape_ratio", T::Number).withUnit("-").defaultsTo("3.0").positive().when(when)
      .describedAs("shape parameter a_r / h (bar1d takes 1.0)");
}

void addSpectralElementOptions(SceneSchema& schema) {
  schema.add("method.order", T::Integer).withUnit("-").defaultsTo("4").between(1, 8).when("name = spectral_element")
      .describedAs("GLL order N (elements N spacings wide, so geometry.spacing is the mean node spacing)");
}

void noOptions(SceneSchema&) {}

std::vector<MethodEntry> makeCatalogue() {
  const std::vector<std::string> secondOrder = secondOrderIntegratorNames();
  std::vector<MethodEntry> list;

  // Cost figures: whole runs of the shipped scenes on one core of this project's reference machine
  // (2 cores of an AMD EPYC at 2.6 GHz), peak memory and wall time from the runs' summary.json; see
  // docs/studies/which-method.md for prediction beside measurement and
  // analysis/calibrate_catalogue.py for how they were measured.
  {
    MethodEntry m;
    m.name = "finite_difference";
    m.title = "Finite differences: the reference scalar wave";
    m.summary = "rho u_tt = (lambda + 2 mu) Lap u by the second-order (2D+1)-point Laplacian on a lattice, applied "
                "matrix-free from one stencil per row type; the reference with a closed-form symbol.";
    m.supports = {{1, 2, 3}, {"line", "rectangle", "block"}, {B::Free, B::Fixed}, {L::PointForce}, secondOrder};
    m.addOptions = noOptions;
    m.stepRule = "cfl x 2 / omega_max, omega_max from a power iteration on the lattice operator (bounded by Gershgorin)";
    m.cost.baseMiB = 12;
    m.cost.bytesPerParticle = {60, 60, 60};
    m.cost.particleStepsPerSecond = {1.0e8, 1.0e8, 6.0e7};
    m.cost.setupSecondsPerParticle = {2e-7, 2e-7, 2e-7};
    m.programs = {"wavefield", "wave1d"};
    list.push_back(m);
  }
  {
    MethodEntry m;
    m.name = "very_weak_sph";
    m.title = "Very weak form SPH for linear elastodynamics (Ding, Long, Wu)";
    m.summary = "the kernel-Hessian operator with boundary integrals, tractions and patch loads, Lysmer-Kuhlemeyer "
                "dashpots; variants: galerkin (tent kernel as test and trial function, symmetric, stable without "
                "a filter), consistent (patch-test exact rows), published (as printed: does not converge).";
    m.variants = {"galerkin", "consistent", "published"};
    m.supports = {{2, 3},
                  {"rectangle", "block"},
                  {B::Free, B::Fixed, B::Traction, B::Displacement, B::Transmitting},
                  {L::SurfacePatch},
                  secondOrder};
    m.addOptions = addVeryWeakSphKeys;
    m.stepRule = "cfl x 2 / omega_max of M^-1 K, omega_max from a power iteration on the assembled operator";
    m.cost.baseMiB = 40;
    m.cost.bytesPerParticle = {300, 300, 300};
    m.cost.particleStepsPerSecond = {1.2e7, 1.2e7, 1.1e7};
    m.cost.setupSecondsPerParticle = {3e-6, 3e-6, 4e-6};
    m.programs = {"lamb2d", "lamb3d", "plate"};
    list.push_back(m);
  }
  {
    MethodEntry m;
    m.name = "reproducing_kernel";
    m.title = "Reproducing-kernel collocation (Luo, Liu, Huang)";
    m.summary = "strong-form collocation with cubic B-spline RK shape functions of order m, consistent mass, "
                "traction rows on free faces; central difference on its explicit form or Newmark.";
    m.supports = {{1, 2, 3},
                  {"line", "rectangle", "block"},
                  {B::Free, B::Fixed, B::Traction, B::Transmitting},
                  {L::SurfacePatch},
                  {"central_difference", "newmark"}};
    m.addOptions = addCollocationOptions;
    m.stepRule = "cfl x 2 / omega_max of the constrained system (power iteration), refused when its interior rows "
                 "grow (stability atlas)";
    m.cost.baseMiB = 40;
    m.cost.bytesPerParticle = {6000, 20000, 60000};
    m.cost.particleStepsPerSecond = {2.0e6, 6.0e5, 2.0e5};
    m.cost.setupSecondsPerParticle = {2e-5, 1e-4, 1e-3};
    m.programs = {"bar1d", "plane2d", "lamb2d", "lamb3d"};
    list.push_back(m);
  }
  {
    MethodEntry m;
    m.name = "radial_basis";
    m.title = "Radial-basis collocation (Luo, Liu, Huang)";
    m.summary = "strong-form collocation with global inverse-multiquadric (or other) radial basis shape functions; "
                "1-D only (a 2-D or 3-D row would be a dense solve over the whole block).";
    m.supports = {{1}, {"line"}, {B::Free, B::Fixed, B::Traction}, {}, {"central_difference", "newmark"}};
    m.addOptions = addRadialBasisOptions;
    m.stepRule = "cfl x 2 / omega_max of the constrained system (power iteration)";
    m.cost.baseMiB = 12;
    m.cost.bytesPerParticle = {20000, 0, 0};
    m.cost.particleStepsPerSecond = {2.0e6, 0, 0};
    m.cost.setupSecondsPerParticle = {1e-4, 0, 0};
    m.programs = {"bar1d"};
    list.push_back(m);
  }
  {
    MethodEntry m;
    m.name = "spectral_element";
    m.title = "Spectral elements: the seismologists' reference";
    m.summary = "GLL points of order N on square / cubic elements N spacings wide, lumped mass, applied matrix-free "
                "(sum factorisation in 3-D); free, fixed, Lysmer-Kuhlemeyer and periodic faces, exact patch tractions.";
    m.supports = {{2, 3}, {"rectangle", "block"}, {B::Free, B::Fixed, B::Transmitting}, {L::SurfacePatch},
                  {"central_difference"}};
    m.addOptions = addSpectralElementOptions;
    m.interiorRow = InteriorRow::SpectralElement;
    m.stepRule = "cfl x 2 / omega_max, omega_max from a Gershgorin bound on the element operator";
    m.cost.baseMiB = 40;
    m.cost.bytesPerParticle = {400, 400, 400};
    m.cost.particleStepsPerSecond = {5.0e6, 5.0e6, 2.0e6};
    m.cost.setupSecondsPerParticle = {2e-6, 2e-6, 3e-6};
    m.programs = {"lamb2d", "lamb3d", "planewave"};
    list.push_back(m);
  }
  {
    MethodEntry m;
    m.name = "updated_lagrangian_sph";
    m.title = "Updated-Lagrangian SPH for solids (Li's primer)";
    m.summary = "density, equation of state, Jaumann hypoelasticity, artificial viscosity and stress, XSPH, "
                "kernel-gradient correction; a large-deformation method on moving particles, first-order integrators.";
    m.supports = {{1, 2, 3},
                  {"line", "rectangle", "block"},
                  {B::Free, B::Fixed, B::Traction},
                  {L::SurfacePatch, L::BodyForce},
                  firstOrderIntegratorNames(),
                  true};
    m.addOptions = addUpdatedLagrangianSphKeys;
    m.stepRule = "cfl x the method's own CFL, viscous and force criteria, evaluated before every step";
    m.cost.baseMiB = 40;
    m.cost.bytesPerParticle = {1500, 2500, 6000};
    m.cost.particleStepsPerSecond = {2.0e6, 1.0e6, 2.5e5};
    m.cost.setupSecondsPerParticle = {1e-6, 2e-6, 5e-6};
    m.programs = {"bar1d_sph", "plate", "rings", "lamb2d", "lamb3d"};
    list.push_back(m);
  }
  {
    MethodEntry m;
    m.name = "total_lagrangian_sph";
    m.title = "Total-Lagrangian SPH for elastic solids";
    m.summary = "reference-configuration pairs computed once, corrected kernel gradients, Saint Venant-Kirchhoff "
                "stress, a variational hourglass penalty, no artificial terms; a case of the plate study.";
    m.supports = {{2}, {"rectangle"}, {B::Free, B::Fixed}, {}, {"central_difference"}};
    m.addOptions = noOptions;
    m.stepRule = "cfl x 2 / omega_max of the linearised operator (power iteration)";
    m.cost.baseMiB = 40;
    m.cost.bytesPerParticle = {0, 3000, 0};
    m.cost.particleStepsPerSecond = {0, 1.5e6, 0};
    m.cost.setupSecondsPerParticle = {0, 2e-5, 0};
    m.programs = {"plate"};
    list.push_back(m);
  }
  return list;
}

}  // namespace

const std::vector<MethodEntry>& methodCatalogue() {
  static const std::vector<MethodEntry> catalogue = makeCatalogue();
  return catalogue;
}

const MethodEntry* findMethod(const std::string& name) {
  for (const MethodEntry& m : methodCatalogue())
    if (m.name == name) return &m;
  return nullptr;
}

std::vector<std::string> methodNames() {
  std::vector<std::string> names;
  for (const MethodEntry& m : methodCatalogue()) names.push_back(m.name);
  return names;
}

const MethodEntry& methodNamed(const std::string& name, const std::string& key) {
  if (const MethodEntry* m = findMethod(name)) return *m;
  std::string problem = "'" + name + "' is not in the method catalogue (" + scene::joinNames(methodNames()) + ")";
  if (const auto close = scene::closestMatch(name, methodNames())) problem += "; did you mean '" + *close + "'?";
  throw InputError(key, problem);
}

SceneSchema catalogueSchema(const MethodEntry& method) {
  SceneSchema schema = SceneSchema::common();
  for (const MethodEntry& m : methodCatalogue())
    if (m.name != "finite_difference" && schema.find("method.name") && m.name != method.name) {
      const auto& choices = schema.at("method.name").choices;
      if (std::find(choices.begin(), choices.end(), m.name) == choices.end()) schema.addChoice("method.name", m.name);
    }
  method.addOptions(schema);  // registers its own name as a choice where its keys do
  const auto& choices = schema.at("method.name").choices;
  if (std::find(choices.begin(), choices.end(), method.name) == choices.end()) schema.addChoice("method.name", method.name);
  if (method.supports.firstOrder) useFirstOrderIntegrators(schema);
  return schema;
}

}  // namespace mfwave
