#pragma once
// Strong-form collocation of linear elastodynamics (Luo-Liu-Huang eqs. (7)-(24)):
//
//   S d''(t) + A d(t) = b(t)                                                   eq. (24)
//
// (the printed "A d-dot" of eq. (24) is a typo: eq. (23) has A d). Rows are collocation points
// xi_r times components, columns source nodes J times components (dof = index * D + component):
//
//   interior point     S = rho psi_J(xi) I,  A = -L psi_J(xi),  b = f(xi, t)   (body force)
//   traction point     S = 0,                A = B^h psi_J(xi), b = h(xi, t)   (sigma(u) n = h)
//   displacement point S = 0,                A = psi_J(xi) I,   b = g(xi, t)   (u = g)
//
// with the (positive) elasticity operator written out per dimension:
//   1-D (thin bar):     L u = E u,xx                    E = Material::youngsModulus()
//   2-D plane strain:   L u = (lambda + mu) grad div u + mu Lap u    (Luo-Liu-Huang eq. (12))
//   3-D (Navier):       L u = (lambda + mu) grad div u + mu Lap u
// and the tractions sigma(u) n = lambda (div u) n + mu (grad u + grad u^T) n (eq. (13)); in 1-D
// sigma n = E u,x n. So an interior row reads rho u'' - L u = f. Nc >= Ns is allowed (least
// squares downstream). The 1-D modulus is E, not lambda + 2 mu: build the bar material with
// Material::fromYoung(E, 0, rho), for which both agree.

#include <functional>
#include <vector>

#include "core/Material.hpp"
#include "particles/ParticleSet.hpp"
#include "core/Types.hpp"
#include "methods/collocation/ShapeFunctions.hpp"

namespace mfwave {

enum class CollocationRowKind { Interior, Traction, Displacement };

// The collocation points xi, what each one enforces, and (traction points) the outward unit normal.
template <int D>
struct CollocationPoints {
  std::vector<Vec<D>> points;
  std::vector<CollocationRowKind> kind;
  std::vector<Vec<D>> normal;  // same length as points; ignored except for Traction points

  std::size_t size() const { return points.size(); }
  void add(const Vec<D>& x, CollocationRowKind k, const Vec<D>& n = Vec<D>::Zero()) {
    points.push_back(x);
    kind.push_back(k);
    normal.push_back(n);
  }
};

// The collocation points of a bar on the nodes x_0 < ... < x_{N-1} (Nc = Ns): a displacement row
// at x_0 (u(x_0) = g), a traction row at x_{N-1} with outward normal +1 (E u_x = h), interior rows
// between: the fixed-free bar of Luo-Liu-Huang's example.
CollocationPoints<1> fixedFreeBarPoints(const Coordinates<1>& nodes);

// Body force f(x, t), prescribed traction h(x, n, t), prescribed displacement g(x, t).
// An empty function means zero.
template <int D>
struct CollocationLoads {
  std::function<Vec<D>(const Vec<D>& x, Real t)> bodyForce;
  std::function<Vec<D>(const Vec<D>& x, const Vec<D>& normal, Real t)> traction;
  std::function<Vec<D>(const Vec<D>& x, Real t)> displacement;
};

struct CollocationSystem {
  SparseMatrix S;                          // (Nc D) x (Ns D)
  SparseMatrix A;                          // (Nc D) x (Ns D)
  std::vector<CollocationRowKind> rowKind; // per row (Nc D entries)
  int components = 1;                      // D
  std::function<void(Real t, Vector& b)> load;  // fills b(t), resized to rows; empty: b = 0
  Real density = 1;                        // rho of the interior rows (S_I = rho Psi_I)

  Index rows() const { return A.rows(); }
  Index cols() const { return A.cols(); }
  // b(t), of size rows() (zero when load is empty).
  Vector rhs(Real t) const;
};

// Assembles S, A and b(t). Throws InputError("collocation.points") when the arrays of `points`
// differ in length or a traction normal is not of unit length, and whatever the shape functions
// throw (InputError("method.support") where a point has too few nodes).
template <int D>
CollocationSystem assembleCollocation(const ShapeFunctions<D>& shapes, const CollocationPoints<D>& points,
                                      const Material& material, const CollocationLoads<D>& loads = {});

// The field u^h(x) = sum_J psi_J(x) d_J at `points`: a vector of points.size() * D values
// (layout point * D + component). With derivative = 1 and axis k: d u^h / dx_k instead.
template <int D>
Vector evaluateCollocationField(const ShapeFunctions<D>& shapes, const Vector& coefficients,
                                const std::vector<Vec<D>>& points, int derivative = 0, int axis = 0);

// Expands a scalar shape-function matrix (rows points, columns nodes) to D components:
// entry (r D + i, J D + i) = psi(r, J) for every i.
SparseMatrix expandComponents(const SparseMatrix& scalar, int components);

extern template CollocationSystem assembleCollocation<1>(const ShapeFunctions<1>&, const CollocationPoints<1>&,
                                                         const Material&, const CollocationLoads<1>&);
extern template CollocationSystem assembleCollocation<2>(const ShapeFunctions<2>&, const CollocationPoints<2>&,
                                                         const Material&, const CollocationLoads<2>&);
extern template CollocationSystem assembleCollocation<3>(const ShapeFunctions<3>&, const CollocationPoints<3>&,
                                                         const Material&, const CollocationLoads<3>&);
extern template Vector evaluateCollocationField<1>(const ShapeFunctions<1>&, const Vector&,
                                                   const std::vector<Vec<1>>&, int, int);
extern template Vector evaluateCollocationField<2>(const ShapeFunctions<2>&, const Vector&,
                                                   const std::vector<Vec<2>>&, int, int);
extern template Vector evaluateCollocationField<3>(const ShapeFunctions<3>&, const Vector&,
                                                   const std::vector<Vec<3>>&, int, int);

}  // namespace mfwave
