#pragma once
// Small value types shared by every layer. Fixed-size Eigen types for points and tensors in
// 1, 2 and 3 dimensions; dynamic vectors for the global state of a semi-discrete system.

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cstdint>

namespace mfwave {

using Real = double;
using Index = std::int64_t;  // global particle / degree-of-freedom index (ready for > 2^31 dofs)

// The one definition of pi (C++17 has no std::numbers).
inline constexpr Real kPi = 3.14159265358979323846;

template <int D>
using Vec = Eigen::Matrix<Real, D, 1>;
template <int D>
using Mat = Eigen::Matrix<Real, D, D>;

using Vec1 = Vec<1>;
using Vec2 = Vec<2>;
using Vec3 = Vec<3>;
using Mat1 = Mat<1>;
using Mat2 = Mat<2>;
using Mat3 = Mat<3>;

// Global state vector of a semi-discrete system (displacements, velocities, ...).
// Layout convention for vector fields on particles: dof = particle * components + component.
using Vector = Eigen::VectorXd;
using SparseMatrix = Eigen::SparseMatrix<Real, Eigen::ColMajor, int>;
using Triplet = Eigen::Triplet<Real, int>;

}  // namespace mfwave
