#include "studies/solid/SolidParticleFill.hpp"

#include "core/Error.hpp"
#include "io/scene/Format.hpp"
#include "methods/collocation/ReproducingKernelShapeFunctions.hpp"

#include <algorithm>
#include <cmath>

namespace mfwave::solid {

template <int D>
Real FilledSolid<D>::ratioFor(Real ratio, Real dx) const {
  return ratio * dx / std::pow(volume / static_cast<Real>(fill.size()), Real(1) / D);
}

template <int D>
FilledSolid<D> fillSolid(const SolidPlan<D>& plan, Real spacing, SolidCaseResult& result) {
  FilledSolid<D> out;
  out.fill = fill<D>(*plan.solid.solid, spacing, scene::vectorOf<D>(plan.scene.geometry.lower));
  for (Index i = 0; i < out.fill.size(); ++i) {
    const auto k = static_cast<std::size_t>(i);
    out.particles.add(out.fill.position[k], out.fill.volume[k]);
    out.volume += out.fill.volume[k];
    out.surfaceParticles += out.fill.surface[k];
  }
  result.unknowns = out.fill.size();
  result.volume = out.volume;
  result.cutCells = out.surfaceParticles;
  return out;
}

template <int D>
std::vector<std::pair<Index, Vec<D>>> surfaceForces(const SolidPlan<D>& plan, const FilledSolid<D>& filled,
                                                    std::size_t l, Real spacing) {
  const LoadSpec& load = plan.scene.loads[l];  // surface_traction: the catalogue refuses the others
  const Solid<D>& solid = *plan.solid.solid;
  const SolidParticles<D>& f = filled.fill;
  const Vec<D> centre = scene::vectorOf<D>(load.centre);
  const bool pressure = load.traction.empty();
  std::vector<std::pair<Index, Vec<D>>> out;
  for (Index i = 0; i < f.size(); ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (!f.surface[k]) continue;
    const Vec<D> x = f.position[k];
    const Vec<D> p = x - solid.signedDistance(x) * solid.normal(x);
    if (solid.surfaceName(p) != load.surface) continue;
    const Real area = f.area[k];
    const Real s = D == 2 ? area : std::sqrt(area);
    if (!(s > 0)) continue;
    const Real w = surfaceLoadShare(load.radius, (p - centre).norm(), s);
    if (w == 0) continue;
    const Vec<D> traction = pressure ? Vec<D>(-load.pressure * f.normal[k]) : scene::vectorOf<D>(load.traction);
    out.emplace_back(i, Vec<D>(w * area * traction));
  }
  if (out.empty())
    throw InputError("load[" + std::to_string(l) + "].surface",
                     "no surface particle of '" + load.surface + "' lies within " + scene::formatNumber(load.radius) +
                         " of " + scene::formatPoint(load.centre) + " at spacing " + scene::formatNumber(spacing));
  return out;
}

template <int D>
std::function<bool(Index, Index)> crackFilter(const SolidPlan<D>& plan, const FilledSolid<D>& filled) {
  if (plan.solid.cracks.empty()) return {};
  return [&plan, &filled](Index i, Index j) {
    return plan.solid.cracks.visible(filled.fill.position[static_cast<std::size_t>(i)],
                                     filled.fill.position[static_cast<std::size_t>(j)]);
  };
}

template <int D>
std::function<std::string(long)> particleWhere(const FilledSolid<D>& filled, const std::string& method,
                                               const std::string& caseName) {
  return [&filled, method, caseName](long particle) -> std::string {
    if (particle >= filled.fill.size()) return "";
    const Vec<D> x = filled.fill.position[static_cast<std::size_t>(particle)];
    return method + " on the solid, case " + caseName + ": the particle starts at " +
           scene::formatPoint(std::vector<Real>(x.data(), x.data() + D));
  };
}

template <int D>
std::vector<Index> fixedParticles(const SolidPlan<D>& plan, const FilledSolid<D>& filled) {
  std::vector<Index> out;
  if (plan.fixedSurfaces.empty()) return out;
  const Solid<D>& solid = *plan.solid.solid;
  const SolidParticles<D>& f = filled.fill;
  for (Index i = 0; i < f.size(); ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (!f.surface[k]) continue;
    const Vec<D> x = f.position[k];
    if (plan.fixedAt(Vec<D>(x - solid.signedDistance(x) * solid.normal(x)))) out.push_back(i);
  }
  return out;
}

template <int D>
std::vector<std::vector<std::pair<Index, Real>>> probeRows(const SolidPlan<D>& plan, const FilledSolid<D>& filled,
                                                           Real spacing, Real scale) {
  const ReproducingKernelShapeFunctions<D> shapes(filled.particles, 1, 2.5 * spacing);
  return shapeFunctionRows(shapes, plan.probes, scale);
}

template struct FilledSolid<2>;
template struct FilledSolid<3>;
template FilledSolid<2> fillSolid<2>(const SolidPlan<2>&, Real, SolidCaseResult&);
template FilledSolid<3> fillSolid<3>(const SolidPlan<3>&, Real, SolidCaseResult&);
template std::vector<std::pair<Index, Vec<2>>> surfaceForces<2>(const SolidPlan<2>&, const FilledSolid<2>&, std::size_t, Real);
template std::vector<std::pair<Index, Vec<3>>> surfaceForces<3>(const SolidPlan<3>&, const FilledSolid<3>&, std::size_t, Real);
template std::function<bool(Index, Index)> crackFilter<2>(const SolidPlan<2>&, const FilledSolid<2>&);
template std::function<bool(Index, Index)> crackFilter<3>(const SolidPlan<3>&, const FilledSolid<3>&);
template std::function<std::string(long)> particleWhere<2>(const FilledSolid<2>&, const std::string&, const std::string&);
template std::function<std::string(long)> particleWhere<3>(const FilledSolid<3>&, const std::string&, const std::string&);
template std::vector<Index> fixedParticles<2>(const SolidPlan<2>&, const FilledSolid<2>&);
template std::vector<Index> fixedParticles<3>(const SolidPlan<3>&, const FilledSolid<3>&);
template std::vector<std::vector<std::pair<Index, Real>>> probeRows<2>(const SolidPlan<2>&, const FilledSolid<2>&, Real, Real);
template std::vector<std::vector<std::pair<Index, Real>>> probeRows<3>(const SolidPlan<3>&, const FilledSolid<3>&, Real, Real);

}  // namespace mfwave::solid
