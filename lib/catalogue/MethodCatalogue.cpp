#include "catalogue/MethodCatalogue.hpp"

#include "core/Error.hpp"
#include "integrators/FirstOrderIntegratorFactory.hpp"
#include "integrators/IntegratorFactory.hpp"
#include "io/scene/Format.hpp"
#include "io/scene/IntegratorSpec.hpp"
#include "wiring/CollocationSpec.hpp"
#include "wiring/UpdatedLagrangianSphSpec.hpp"
#include "wiring/VeryWeakSphSpec.hpp"

#include <algorithm>

namespace mfwave {
namespace {

using B = BoundaryType;
using L = LoadType;
using T = ValueType;

// Collocation's keys are declared once, beside their reader (wiring/CollocationSpec); their defaults
// are each study's, which the listing says.
void addCollocationOptions(SceneSchema& schema) {
  CollocationKeyDefaults keys;
  keys.supportNote = "the study's: 2.5 in 1-D and 2-D (bar1d 3.3), 2.2 in 3-D";
  keys.supportAdvice = "from about 2.77 in 2-D and 2.5 in 3-D the interior rows grow";
  addCollocationKeys(schema, keys);
}

void addRadialBasisOptions(SceneSchema& schema) {
  CollocationKeyDefaults keys;
  keys.reproducingKernel = false;
  keys.radialBasis = true;
  keys.shapeRatio = 1.0;  // bar1d's (the paper's), the one program that runs it
  addCollocationKeys(schema, keys);
}

void addSpectralElementOptions(SceneSchema& schema) {
  schema.add("method.order", T::Integer).withUnit("-").defaultsTo("4").between(1, 8).when("name = spectral_element")
      .describedAs("GLL order N (elements N spacings wide, so geometry.spacing is the mean node spacing)");
}

void noOptions(SceneSchema&) {}

std::vector<MethodEntry> makeCatalogue() {
  const std::vector<std::string> secondOrder = secondOrderIntegratorNames();
  std::vector<MethodEntry> list;

  // Cost figures: whole runs of the shipped scenes on one core (OMP_NUM_THREADS=1) of this project's
  // reference machine (2 cores of an AMD EPYC, 2026-11-28), set-up, loop and peak memory from each
  // case's record in summary.json; analysis/catalogue_check.py sets the predictions beside runs
  // (docs/studies/which-method.md).
  {
    MethodEntry m;
    m.name = "finite_difference";
    m.title = "Finite differences: the reference scalar wave";
    m.summary = "rho u_tt = (lambda + 2 mu) Lap u by the second-order (2D+1)-point Laplacian on a lattice, applied "
                "matrix-free from one stencil per row type; the reference with a closed-form symbol.";
    m.supports = {{1, 2, 3}, {"line", "rectangle", "block"}, {B::Free, B::Fixed}, {L::PointForce}, secondOrder};
    m.addOptions = noOptions;
    m.stepRule = "cfl x 2 / omega_max, omega_max from a power iteration on the lattice operator (bounded by Gershgorin)";
    m.cost.baseMiB = {30, 30, 30};
    m.cost.bytesPerParticle = {51, 51, 51};
    m.cost.particleStepsPerSecond = {4.3e7, 4.3e7, 4.3e7};
    m.cost.setupSecondsPerParticle = {6e-6, 6e-6, 6e-6};
    m.cost.measured = "wavefield, block-ricker.toml at dx = 0.1, 0.05, 0.025 (3-D; 1-D and 2-D assumed the same)";
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
                  {B::Free, B::Fixed, B::Traction, B::Displacement, B::Transmitting, B::Symmetry},
                  {L::SurfacePatch, L::PointForce, L::MomentTensor, L::SurfaceTraction},
                  secondOrder};
    m.supports.solidPrograms = {"solid"};  // the galerkin variant on cut cells
    m.supports.materialRegions = true;      // materials per Gauss point of the cut cells
    m.cost.solidBaseMiB = {0, 40, 150};
    m.cost.solidBytesPerParticle = {0, 3100, 23500};
    m.cost.solidParticleStepsPerSecond = {0, 3.0e7, 4.0e6};
    m.cost.solidSetupSecondsPerParticle = {0, 1.0e-5, 1.5e-4};
    m.cost.solidMeasured = "the solid study, cut cells and staircase in one run: lamb2d_inclined.toml at dx = 0.0625 "
                           "and 0.03125 (2-D); a half-space with a ball cavity at dx = 0.125 and 0.0625 (3-D)";
    m.addOptions = addVeryWeakSphKeys;
    m.stepRule = "cfl x 2 / omega_max of M^-1 K, omega_max from a power iteration on the assembled operator";
    m.cost.baseMiB = {0, 31.9, 35};
    m.cost.bytesPerParticle = {0, 190, 280};
    m.cost.particleStepsPerSecond = {0, 4.7e7, 1.55e7};
    m.cost.setupSecondsPerParticle = {0, 7e-6, 6.5e-6};
    m.cost.measured = "lamb2d.toml at dx = 0.25, 0.125, 0.0625 (galerkin; consistent at 0.25: 0.8 x the rate), "
                      "lamb3d.toml at dx = 0.5, 0.25";
    m.programs = {"lamb2d", "lamb3d", "plate", "solid"};
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
                  {B::Free, B::Fixed, B::Traction},
                  {L::SurfacePatch, L::SurfaceTraction},
                  {"central_difference", "newmark"},
                  false,
                  {{B::Transmitting, B::Fixed}}};
    // lattice nodes well inside the solid, nodes with traction rows on its surfaces; one material (a
    // strong form across an interface would need rows of its own: traction continuity)
    m.supports.solidPrograms = {"solid"};
    m.supports.fixedSurfaces = true;  // displacement rows at the surface nodes
    m.addOptions = addCollocationOptions;
    m.stepRule = "cfl x 2 / omega_max of the constrained system (power iteration), refused when its interior rows "
                 "grow (stability atlas)";
    // The sparse LU of the shape-function matrix fills as nodes^1.41 (3-D) and its solve dominates
    // both the set-up and the step: memory, set-up and step per node grow with N.
    m.cost.baseMiB = {12, 31.5, 35};
    m.cost.bytesPerParticle = {2000, 16000, 0};
    m.cost.fillMiB = {0, 0, 4167};
    m.cost.fillNodes = 24389;
    m.cost.fillExponent = 1.41;
    m.cost.growthNodes = {321, 561, 3375};
    m.cost.growthExponent = 1.45;
    m.cost.particleStepsPerSecond = {3.9e6, 1.5e6, 1.4e5};
    m.cost.setupSecondsPerParticle = {1.9e-4, 2.3e-4, 2.5e-3};
    m.cost.measured = "bar1d.toml at 321 nodes; lamb2d.toml at dx = 0.5, 0.25; lamb3d.toml at dx = 0.5 (3375 nodes, "
                      "255 MiB) and the 4.1 GiB measured at 24,389";
    m.programs = {"bar1d", "plane2d", "lamb2d", "lamb3d", "solid"};
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
    m.cost.baseMiB = {12, 0, 0};
    m.cost.bytesPerParticle = {2000, 0, 0};
    m.cost.particleStepsPerSecond = {3.9e6, 0, 0};
    m.cost.setupSecondsPerParticle = {1.9e-4, 0, 0};
    m.cost.measured = "assumed RK collocation's in 1-D (bar1d.toml runs both at 21 to 321 nodes)";
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
    m.cost.baseMiB = {0, 31.5, 35};
    m.cost.bytesPerParticle = {0, 280, 250};
    m.cost.particleStepsPerSecond = {0, 2.7e7, 1.07e7};
    m.cost.setupSecondsPerParticle = {0, 1.5e-6, 4.4e-6};
    m.cost.measured = "lamb2d.toml at dx = 0.25, 0.125 and lamb3d.toml at dx = 0.4375, N = 4";
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
                  {L::SurfacePatch, L::BodyForce, L::SurfaceTraction},
                  firstOrderIntegratorNames(),
                  true,
                  {{B::Transmitting, B::Free}}};
    // the rings: two annulus shapes with opposite initial velocities; solid: a body-fitted fill at small amplitude
    m.supports.solidPrograms = {"rings", "solid"};
    m.supports.cracks = true;         // pairs across a crack are cut (the visibility criterion)
    m.supports.fixedSurfaces = true;  // the surface particles clamped
    m.addOptions = addUpdatedLagrangianSphKeys;
    m.stepRule = "cfl x the method's own CFL, viscous and force criteria, evaluated before every step";
    m.cost.baseMiB = {33, 32.1, 35};
    m.cost.bytesPerParticle = {1000, 1070, 2200};
    m.cost.particleStepsPerSecond = {1.2e7, 3.1e6, 6.5e5};
    m.cost.setupSecondsPerParticle = {1.2e-6, 1.2e-6, 5e-6};
    m.cost.measured = "bar1d-sph.toml at 800 particles; lamb2d.toml at dx = 0.25, 0.125; lamb3d.toml at dx = 0.5";
    m.programs = {"bar1d_sph", "plate", "rings", "lamb2d", "lamb3d", "solid"};
    list.push_back(m);
  }
  {
    MethodEntry m;
    m.name = "total_lagrangian_sph";
    m.title = "Total-Lagrangian SPH for elastic solids";
    m.summary = "reference-configuration pairs computed once, corrected kernel gradients, Saint Venant-Kirchhoff "
                "stress, a variational hourglass penalty, no artificial terms; a case of the plate study and of the "
                "solid study.";
    m.supports = {{2},
                  {"rectangle"},
                  {B::Free, B::Fixed},
                  {L::SurfaceTraction},
                  {"central_difference"},
                  false,
                  {{B::Transmitting, B::Free}}};
    m.supports.solidPrograms = {"solid"};  // a body-fitted fill at small amplitude, one material
    m.supports.fixedSurfaces = true;       // the surface particles clamped
    m.supports.cracks = true;              // reference pairs across a crack left out
    m.addOptions = noOptions;
    m.stepRule = "cfl x 2 / omega_max of the linearised operator (power iteration)";
    m.cost.baseMiB = {0, 30, 0};
    m.cost.bytesPerParticle = {0, 2000, 0};
    m.cost.particleStepsPerSecond = {0, 1.18e7, 0};
    m.cost.setupSecondsPerParticle = {0, 1.5e-5, 0};
    m.cost.measured = "plate.toml's tlsph case at H / dp = 5 (265 particles; memory per particle not resolved there)";
    m.programs = {"plate", "solid"};
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

bool runsIn(const MethodEntry& method, const std::string& program) {
  return std::find(method.programs.begin(), method.programs.end(), program) != method.programs.end();
}

std::vector<std::string> methodsRunBy(const std::string& program) {
  std::vector<std::string> names;
  for (const MethodEntry& m : methodCatalogue())
    if (runsIn(m, program)) names.push_back(m.name);
  return names;
}

SceneSchema catalogueSchema(const MethodEntry& method) {
  SceneSchema schema = SceneSchema::common();
  // addChoice keeps each name once: the others first, then the method's own keys (which may add its
  // name), then its name where its keys do not.
  for (const MethodEntry& m : methodCatalogue())
    if (m.name != method.name) schema.addChoice("method.name", m.name);
  method.addOptions(schema);
  schema.addChoice("method.name", method.name);
  if (method.supports.firstOrder) useFirstOrderIntegrators(schema);
  return schema;
}

}  // namespace mfwave
