#include "wiring/VeryWeakSphScene.hpp"

#include "core/Error.hpp"
#include "io/scene/Format.hpp"

namespace mfwave {

using scene::vectorOf;

void checkVeryWeakSphScene(const SceneReader& reader, const Scene& scene, const VeryWeakSphSpec& spec,
                           const std::string& program) {
  for (std::size_t i = 0; i < scene.loads.size(); ++i)
    if (scene.loads[i].type != LoadType::SurfacePatch)
      reader.fail("load[" + std::to_string(i) + "].type",
                  program + " takes surface_patch loads (point and body forces have no very weak form here)");
  try {
    checkVeryWeakSphCombination(spec.options.variant, spec.deconvolution, spec.smoothingRate);
  } catch (const InputError& e) {
    reader.fail(e.key(), e.problem());  // the method's refusal, located in the scene
  }
  bool periodic = false;
  for (bool p : scene.geometry.periodic) periodic = periodic || p;
  if (facesWith(scene.boundaries, BoundaryType::Symmetry) != 0 && (spec.operatorStorage == "sparse" || periodic))
    reader.fail("method.operator", "symmetry planes are folded into the lattice stencils; the sparse assembly has "
                                   "no image to fold (use \"auto\" or \"lattice\", on a box without periodic axes)");
  if (scene.integrator.kind == IntegratorKind::CentralDifference) return;
  if (spec.smoothingRate > 0)
    reader.fail("method.smoothing_rate", "conservative smoothing is applied by the central_difference "
                                         "integrator only; set it to 0 to run " + scene.integrator.name);
  if (facesWith(scene.boundaries, BoundaryType::Fixed) != 0 || facesWith(scene.boundaries, BoundaryType::Displacement) != 0)
    reader.fail("boundary", "fixed and displacement faces (eq. 30) need the central_difference integrator");
}

template <int D>
VeryWeakSphProblemSettings<D> veryWeakSphProblemSettings(const Scene& scene, const GeometrySpec& geometry,
                                                         const VeryWeakSphSpec& spec, bool withBoundaries) {
  VeryWeakSphProblemSettings<D> s;
  s.options = spec.options;
  s.kernel = spec.kernel;
  s.smoothingLength = spec.smoothingLengthRatio * geometry.spacing;
  s.lower = vectorOf<D>(geometry.lower);
  s.upper = vectorOf<D>(geometry.upper);
  s.spacing = geometry.spacing;
  s.dashpotLumping = spec.dashpotLumping;
  // Symmetry planes describe the solid (one side of a mirror), not a condition on it: a case
  // without boundaries keeps them.
  s.symmetryFaces = facesWith(scene.boundaries, BoundaryType::Symmetry);
  if (withBoundaries) {
    s.transmittingFaces = facesWith(scene.boundaries, BoundaryType::Transmitting);
    for (const BoundarySpec& b : scene.boundaries) {
      if (b.type == BoundaryType::Traction) s.faceTractions.push_back({b.faceMask, vectorOf<D>(b.traction), &b.timeFunction});
      if (b.type == BoundaryType::Fixed) s.prescribed.push_back({b.faceMask, Vec<D>::Zero(), nullptr});
      if (b.type == BoundaryType::Displacement)
        s.prescribed.push_back({b.faceMask, vectorOf<D>(b.value), &b.timeFunction});
    }
  }
  for (const LoadSpec& load : scene.loads)
    s.patches.push_back({load.face, vectorOf<D>(load.centre), vectorOf<D>(load.halfWidth), vectorOf<D>(load.traction),
                         &load.timeFunction});
  s.smoothingRate = spec.smoothingRate;
  s.smoothingOrder = spec.smoothingOrder;
  s.deconvolution = spec.deconvolution;
  s.ghostLayers = geometry.ghostLayers;
  s.ghostFaces = geometry.ghostFaces;
  // method.operator: "auto" takes the lattice stencils on a box lattice without periodic axes
  // (they run every variant, boundary, filter and the deconvolution), "lattice" insists (and the
  // problem says why not), "sparse" assembles the matrices.
  bool periodic = false;
  for (bool p : geometry.periodic) periodic = periodic || p;
  s.storage = spec.operatorStorage == "lattice" || (spec.operatorStorage == "auto" && !periodic)
                  ? OperatorStorage::Lattice
                  : OperatorStorage::Sparse;
  return s;
}

template VeryWeakSphProblemSettings<1> veryWeakSphProblemSettings<1>(const Scene&, const GeometrySpec&,
                                                                     const VeryWeakSphSpec&, bool);
template VeryWeakSphProblemSettings<2> veryWeakSphProblemSettings<2>(const Scene&, const GeometrySpec&,
                                                                     const VeryWeakSphSpec&, bool);
template VeryWeakSphProblemSettings<3> veryWeakSphProblemSettings<3>(const Scene&, const GeometrySpec&,
                                                                     const VeryWeakSphSpec&, bool);

}  // namespace mfwave
