#include "methods/collocation/CollocationSystem.hpp"

#include <cmath>
#include <string>

#include "core/Error.hpp"

namespace mfwave {

Vector CollocationSystem::rhs(Real t) const {
  Vector b = Vector::Zero(rows());
  if (load) load(t, b);
  if (b.size() != rows()) throw Error("collocation load filled a vector of the wrong size");
  return b;
}

SparseMatrix expandComponents(const SparseMatrix& scalar, int components) {
  std::vector<Triplet> triplets;
  triplets.reserve(static_cast<std::size_t>(scalar.nonZeros()) * static_cast<std::size_t>(components));
  for (int col = 0; col < scalar.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(scalar, col); it; ++it)
      for (int i = 0; i < components; ++i)
        triplets.emplace_back(static_cast<int>(it.row()) * components + i, col * components + i, it.value());
  SparseMatrix out(scalar.rows() * components, scalar.cols() * components);
  out.setFromTriplets(triplets.begin(), triplets.end());
  return out;
}

template <int D>
CollocationSystem assembleCollocation(const ShapeFunctions<D>& shapes, const CollocationPoints<D>& points,
                                      const Material& material, const CollocationLoads<D>& loads) {
  const std::size_t nc = points.points.size();
  if (points.kind.size() != nc || points.normal.size() != nc)
    throw InputError("collocation.points", "points, kind and normal must have the same length");
  const Real rho = material.density();
  const Real lambda = material.lambda(), mu = material.mu();
  const Real young = material.youngsModulus();

  std::vector<Triplet> s, a;
  CollocationSystem system;
  system.components = D;
  system.density = rho;
  system.rowKind.resize(nc * D);
  ShapeFunctionValues<D> values;
  for (std::size_t p = 0; p < nc; ++p) {
    const CollocationRowKind kind = points.kind[p];
    const Vec<D>& x = points.points[p];
    const int row0 = static_cast<int>(p) * D;
    for (int i = 0; i < D; ++i) system.rowKind[p * D + static_cast<std::size_t>(i)] = kind;
    const int derivatives = kind == CollocationRowKind::Interior ? 2 : kind == CollocationRowKind::Traction ? 1 : 0;
    shapes.evaluate(x, derivatives, values);
    const Vec<D>& n = points.normal[p];
    if (kind == CollocationRowKind::Traction && std::abs(n.norm() - 1) > 1e-9)
      throw InputError("collocation.points",
                       "the normal of traction point " + formatPoint<D>(x) + " is not of unit length");
    for (Index k = 0; k < values.size(); ++k) {
      const int col0 = static_cast<int>(values.nodes[static_cast<std::size_t>(k)]) * D;
      const Real psi = values.value[static_cast<std::size_t>(k)];
      switch (kind) {
        case CollocationRowKind::Interior: {
          const Mat<D>& h = values.hessian[static_cast<std::size_t>(k)];
          for (int i = 0; i < D; ++i) s.emplace_back(row0 + i, col0 + i, rho * psi);
          if constexpr (D == 1) {
            a.emplace_back(row0, col0, -young * h(0, 0));
          } else {
            // -(L psi)_ij = -(mu Lap psi delta_ij + (lambda + mu) psi,ij)
            const Real laplacian = h.trace();
            for (int i = 0; i < D; ++i)
              for (int j = 0; j < D; ++j) {
                const Real v = -((i == j ? mu * laplacian : 0.0) + (lambda + mu) * h(i, j));
                if (v != 0) a.emplace_back(row0 + i, col0 + j, v);
              }
          }
          break;
        }
        case CollocationRowKind::Traction: {
          const Vec<D>& g = values.gradient[static_cast<std::size_t>(k)];
          if constexpr (D == 1) {
            a.emplace_back(row0, col0, young * g[0] * n[0]);
          } else {
            // (sigma n)_i = sum_j [lambda n_i g_j + mu (delta_ij g.n + g_i n_j)] d_Jj
            const Real gn = g.dot(n);
            for (int i = 0; i < D; ++i)
              for (int j = 0; j < D; ++j) {
                const Real v = lambda * n[i] * g[j] + mu * ((i == j ? gn : 0.0) + g[i] * n[j]);
                if (v != 0) a.emplace_back(row0 + i, col0 + j, v);
              }
          }
          break;
        }
        case CollocationRowKind::Displacement:
          for (int i = 0; i < D; ++i) a.emplace_back(row0 + i, col0 + i, psi);
          break;
      }
    }
  }
  const int rows = static_cast<int>(nc) * D, cols = static_cast<int>(shapes.nodeCount()) * D;
  system.S.resize(rows, cols);
  system.S.setFromTriplets(s.begin(), s.end());
  system.A.resize(rows, cols);
  system.A.setFromTriplets(a.begin(), a.end());
  system.S.makeCompressed();
  system.A.makeCompressed();

  if (loads.bodyForce || loads.traction || loads.displacement) {
    system.load = [points, loads](Real t, Vector& b) {
      b.setZero(static_cast<Index>(points.points.size()) * D);
      for (std::size_t p = 0; p < points.points.size(); ++p) {
        const Vec<D>& x = points.points[p];
        Vec<D> value = Vec<D>::Zero();
        switch (points.kind[p]) {
          case CollocationRowKind::Interior:
            if (loads.bodyForce) value = loads.bodyForce(x, t);
            break;
          case CollocationRowKind::Traction:
            if (loads.traction) value = loads.traction(x, points.normal[p], t);
            break;
          case CollocationRowKind::Displacement:
            if (loads.displacement) value = loads.displacement(x, t);
            break;
        }
        b.template segment<D>(static_cast<Index>(p) * D) = value;
      }
    };
  }
  return system;
}

template <int D>
Vector evaluateCollocationField(const ShapeFunctions<D>& shapes, const Vector& coefficients,
                                const std::vector<Vec<D>>& points, int derivative, int axis) {
  if (coefficients.size() != shapes.nodeCount() * D)
    throw InputError("collocation.coefficients", "expected " + std::to_string(shapes.nodeCount() * D) + " values");
  if (derivative < 0 || derivative > 1 || axis < 0 || axis >= D)
    throw InputError("method.derivative", "evaluateCollocationField takes derivative 0 or 1 and an axis < D");
  Vector out = Vector::Zero(static_cast<Index>(points.size()) * D);
  ShapeFunctionValues<D> values;
  for (std::size_t p = 0; p < points.size(); ++p) {
    shapes.evaluate(points[p], derivative, values);
    for (Index k = 0; k < values.size(); ++k) {
      const std::size_t kk = static_cast<std::size_t>(k);
      const Real w = derivative == 0 ? values.value[kk] : values.gradient[kk][axis];
      out.template segment<D>(static_cast<Index>(p) * D) +=
          w * coefficients.template segment<D>(values.nodes[kk] * D);
    }
  }
  return out;
}

template CollocationSystem assembleCollocation<1>(const ShapeFunctions<1>&, const CollocationPoints<1>&,
                                                  const Material&, const CollocationLoads<1>&);
template CollocationSystem assembleCollocation<2>(const ShapeFunctions<2>&, const CollocationPoints<2>&,
                                                  const Material&, const CollocationLoads<2>&);
template CollocationSystem assembleCollocation<3>(const ShapeFunctions<3>&, const CollocationPoints<3>&,
                                                  const Material&, const CollocationLoads<3>&);
template Vector evaluateCollocationField<1>(const ShapeFunctions<1>&, const Vector&, const std::vector<Vec<1>>&,
                                            int, int);
template Vector evaluateCollocationField<2>(const ShapeFunctions<2>&, const Vector&, const std::vector<Vec<2>>&,
                                            int, int);
template Vector evaluateCollocationField<3>(const ShapeFunctions<3>&, const Vector&, const std::vector<Vec<3>>&,
                                            int, int);

CollocationPoints<1> fixedFreeBarPoints(const Coordinates<1>& nodes) {
  const std::size_t n = nodes[0].size();
  CollocationPoints<1> points;
  for (std::size_t i = 0; i < n; ++i)
    points.add(Vec1(nodes[0][i]),
               i == 0 ? CollocationRowKind::Displacement
                      : i + 1 == n ? CollocationRowKind::Traction : CollocationRowKind::Interior,
               Vec1(1.0));
  return points;
}

}  // namespace mfwave
