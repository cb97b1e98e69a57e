#include "methods/spectral_element/SpectralElementElasticity.hpp"

#include "core/Error.hpp"
#include "methods/spectral_element/GaussLobattoLegendre.hpp"
#include "particles/BoxFace.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace mfwave {

namespace {

// The number of elements of size h in `length`, or -1 when it is not a whole number.
Index wholeElements(Real length, Real h) {
  const Real count = length / h;
  const Real rounded = std::round(count);
  if (rounded < 1 || std::abs(count - rounded) > 1e-9 * std::max<Real>(1, count)) return -1;
  return static_cast<Index>(rounded);
}

// (M + dt/2 C) a = f - K u - C vHalf with a diagonal M and C (Ding-Long-Wu eq. (32)): a division
// per unknown; prescribed unknowns take their known accelerations (a diagonal matrix does not
// couple them to the others).
class SpectralElementCentredDamping : public CentredDampingSolve {
 public:
  SpectralElementCentredDamping(const SpectralElementElasticity& system, Real dt, std::vector<Index> prescribedDofs)
      : system_(system), prescribed_(std::move(prescribedDofs)) {
    const Vector& m = system.lumpedMass();
    inverse_ = (m + 0.5 * dt * system.dampingDiagonal()).cwiseInverse();
    for (const Index dof : prescribed_)
      if (dof < 0 || dof >= system.size())
        throw InputError("prescribed_displacement", "dof " + std::to_string(dof) + " is outside the system's " +
                                                        std::to_string(system.size()) + " unknowns");
  }

  void acceleration(Real t, const Vector& u, const Vector& vHalf, const Vector& prescribedAcceleration,
                    Vector& a) override {
    a.resize(system_.size());
    system_.residual(t, u.data(), vHalf.data(), a.data());
    a.array() *= inverse_.array();
    for (std::size_t i = 0; i < prescribed_.size(); ++i) a[prescribed_[i]] = prescribedAcceleration[static_cast<Index>(i)];
  }

 private:
  const SpectralElementElasticity& system_;
  std::vector<Index> prescribed_;
  Vector inverse_;
};

}  // namespace

SpectralElementElasticity::SpectralElementElasticity(SpectralElementSettings settings)
    : settings_(std::move(settings)) {
  const int n = settings_.order;
  if (n < 1 || n > 8) throw InputError("order", "the spectral-element order N must be 1 .. 8, got " + std::to_string(n));
  const Real h = settings_.elementSize;
  if (!(h > 0)) throw InputError("elementSize", "must be positive");
  for (int axis = 0; axis < 2; ++axis) {
    const Real length = settings_.upper[axis] - settings_.lower[axis];
    const Index count = wholeElements(length, h);
    if (count < 0) {
      std::ostringstream problem;
      problem << "the side " << length << " along axis " << axis << " is not a whole number of elements of size " << h;
      throw InputError("elementSize", problem.str());
    }
    elements_[static_cast<std::size_t>(axis)] = count;
    nodes_[static_cast<std::size_t>(axis)] = count * n + 1;
  }
  const QuadratureRule rule = gaussLobattoLegendre(n);
  gllNodes_ = rule.nodes;
  gllWeights_ = rule.weights;
  for (int axis = 0; axis < 2; ++axis) {
    std::vector<Real>& coordinates = axisCoordinates_[static_cast<std::size_t>(axis)];
    coordinates.resize(static_cast<std::size_t>(nodes_[static_cast<std::size_t>(axis)]));
    for (Index e = 0; e < elements_[static_cast<std::size_t>(axis)]; ++e)
      for (int a = 0; a <= n; ++a)
        coordinates[static_cast<std::size_t>(e * n + a)] =
            settings_.lower[axis] + h * (static_cast<Real>(e) + 0.5 * (1 + gllNodes_[static_cast<std::size_t>(a)]));
    coordinates.back() = settings_.upper[axis];
  }
  for (int b = 0; b <= n; ++b)
    for (int a = 0; a <= n; ++a) localOffsets_.push_back(static_cast<Index>(b) * nodes_[0] + a);
  fixed_.assign(static_cast<std::size_t>(size()), 0);
  for (int face = 0; face < 4; ++face) {
    if (settings_.faces[static_cast<std::size_t>(face)] != SpectralElementFace::Fixed) continue;
    const int axis = faceAxis(face);
    const Index line = faceSign(face) < 0 ? 0 : nodes_[static_cast<std::size_t>(axis)] - 1;
    for (Index k = 0; k < nodes_[static_cast<std::size_t>(1 - axis)]; ++k) {
      const Index node = axis == 0 ? k * nodes_[0] + line : line * nodes_[0] + k;
      fixed_[static_cast<std::size_t>(2 * node)] = fixed_[static_cast<std::size_t>(2 * node + 1)] = 1;
    }
  }
  buildElementStiffness();
  buildMassAndDamping();
  buildLoads();
}

// K_e = sum_{p,q} w_p w_q J B^T D B (Komatitsch & Tromp 1999, eq. 19 ff.): with g_l the gradient of
// phi_l at the point, the (l, c), (m, d) entry is lambda g_l[c] g_m[d] + mu (g_l[d] g_m[c] +
// delta_cd g_l . g_m). On the square x = x0 + h/2 (1 + xi), d/dx = 2/h d/dxi and J = h^2 / 4; a
// gradient at a GLL point is one row of the derivative matrix D along one axis.
void SpectralElementElasticity::buildElementStiffness() {
  const int n = settings_.order;
  const int points = n + 1;
  const int local = points * points;
  const Eigen::MatrixXd derivative = lagrangeDerivativeMatrix(gllNodes_);
  const Real h = settings_.elementSize;
  const Real scale = 2 / h, jacobian = 0.25 * h * h;
  const Real lambda = settings_.material.lambda(), mu = settings_.material.mu();
  elementStiffness_ = Eigen::MatrixXd::Zero(2 * local, 2 * local);
  Eigen::MatrixXd gradients(local, 2);
  for (int q = 0; q < points; ++q)
    for (int p = 0; p < points; ++p) {
      gradients.setZero();
      for (int b = 0; b < points; ++b)
        for (int a = 0; a < points; ++a) {
          const int l = b * points + a;
          if (b == q) gradients(l, 0) = scale * derivative(p, a);
          if (a == p) gradients(l, 1) = scale * derivative(q, b);
        }
      const Real weight = gllWeights_[static_cast<std::size_t>(p)] * gllWeights_[static_cast<std::size_t>(q)] * jacobian;
      for (int l = 0; l < local; ++l) {
        if (gradients(l, 0) == 0 && gradients(l, 1) == 0) continue;
        for (int m = 0; m < local; ++m) {
          if (gradients(m, 0) == 0 && gradients(m, 1) == 0) continue;
          const Real dot = gradients(l, 0) * gradients(m, 0) + gradients(l, 1) * gradients(m, 1);
          for (int c = 0; c < 2; ++c)
            for (int d = 0; d < 2; ++d)
              elementStiffness_(2 * l + c, 2 * m + d) +=
                  weight * (lambda * gradients(l, c) * gradients(m, d) +
                            mu * (gradients(l, d) * gradients(m, c) + (c == d ? dot : 0.0)));
        }
      }
    }
}

void SpectralElementElasticity::buildMassAndDamping() {
  const int n = settings_.order;
  const Real h = settings_.elementSize;
  const Real rho = settings_.material.density();
  // Komatitsch & Tromp 1999: GLL quadrature on the GLL nodes makes M diagonal, rho w_a w_b J.
  mass_ = Vector::Zero(size());
  const Real jacobian = 0.25 * h * h;
  for (Index ey = 0; ey < elements_[1]; ++ey)
    for (Index ex = 0; ex < elements_[0]; ++ex)
      for (int b = 0; b <= n; ++b)
        for (int a = 0; a <= n; ++a) {
          const Index node = globalNode(ex, ey, a, b);
          const Real m = rho * gllWeights_[static_cast<std::size_t>(a)] * gllWeights_[static_cast<std::size_t>(b)] * jacobian;
          mass_[2 * node] += m;
          mass_[2 * node + 1] += m;
        }
  // Lysmer & Kuhlemeyer 1969 dashpots, integrated along the face by the same GLL rule (diagonal C):
  // rho c_p on the normal component, rho c_s on the tangential one, per unit length.
  damping_ = Vector::Zero(size());
  const Real cp = settings_.material.pWaveSpeed(), cs = settings_.material.sWaveSpeed();
  for (int face = 0; face < 4; ++face) {
    if (settings_.faces[static_cast<std::size_t>(face)] != SpectralElementFace::Absorbing) continue;
    hasDamping_ = true;
    const int axis = faceAxis(face), along = 1 - axis;
    const Index line = faceSign(face) < 0 ? 0 : nodes_[static_cast<std::size_t>(axis)] - 1;
    for (Index e = 0; e < elements_[static_cast<std::size_t>(along)]; ++e)
      for (int k = 0; k <= n; ++k) {
        const Index position = e * n + k;
        const Index node = axis == 0 ? position * nodes_[0] + line : line * nodes_[0] + position;
        const Real length = gllWeights_[static_cast<std::size_t>(k)] * 0.5 * h;
        damping_[2 * node + axis] += rho * cp * length;
        damping_[2 * node + along] += rho * cs * length;
      }
  }
  for (Index dof = 0; dof < size(); ++dof)
    if (fixed_[static_cast<std::size_t>(dof)]) damping_[dof] = 0;
}

// f_i = integral over the face of T(x) phi_i ds, exactly: on each element edge the loaded part
// [max(a, e0), min(b, e1)] is integrated by (N + 1)-point Gauss-Legendre, exact for the degree-N
// basis restricted to the edge. When the segment's ends are element boundaries this is the face's
// GLL rule (also exact); when an end falls inside an element the load's jump is integrated exactly
// too, though the degree-N trace cannot follow it (the coarse lamb2d case at spacing 0.25, N = 4:
// elements of side 1, strip ends at +-0.5).
void SpectralElementElasticity::buildLoads() {
  const int n = settings_.order;
  const Real h = settings_.elementSize;
  const QuadratureRule gauss = gaussLegendre(n + 1);
  // the Lagrange basis of the GLL nodes at x in [-1, 1]
  const auto basis = [this, n](Real x, int j) {
    Real value = 1;
    for (int k = 0; k <= n; ++k)
      if (k != j)
        value *= (x - gllNodes_[static_cast<std::size_t>(k)]) /
                 (gllNodes_[static_cast<std::size_t>(j)] - gllNodes_[static_cast<std::size_t>(k)]);
    return value;
  };
  for (const SpectralElementTraction& t : settings_.tractions) {
    if (t.face < 0 || t.face > 3) throw InputError("traction", "face must be 0 .. 3");
    if (!t.history) throw InputError("traction", "needs a time function");
    const int axis = faceAxis(t.face), along = 1 - axis;
    const Real start = t.centre - t.halfWidth, end = t.centre + t.halfWidth;
    const Real tolerance = 1e-9 * h;
    if (!(t.halfWidth > 0) || start < settings_.lower[along] - tolerance || end > settings_.upper[along] + tolerance) {
      std::ostringstream problem;
      problem << "the loaded segment [" << start << ", " << end << "] must have a positive width and lie on the face ["
              << settings_.lower[along] << ", " << settings_.upper[along] << "]";
      throw InputError("traction", problem.str());
    }
    const Index line = faceSign(t.face) < 0 ? 0 : nodes_[static_cast<std::size_t>(axis)] - 1;
    Vector load = Vector::Zero(size());
    for (Index e = 0; e < elements_[static_cast<std::size_t>(along)]; ++e) {
      const Real e0 = settings_.lower[along] + static_cast<Real>(e) * h;
      const Real from = std::max(start, e0), to = std::min(end, e0 + h);
      if (to - from <= tolerance) continue;
      for (std::size_t g = 0; g < gauss.nodes.size(); ++g) {
        const Real x = 0.5 * (from + to) + 0.5 * (to - from) * gauss.nodes[g];
        const Real xi = 2 * (x - e0) / h - 1;
        const Real length = 0.5 * (to - from) * gauss.weights[g];
        for (int k = 0; k <= n; ++k) {
          const Index position = e * n + k;
          const Index node = axis == 0 ? position * nodes_[0] + line : line * nodes_[0] + position;
          const Real phi = basis(xi, k);
          for (int c = 0; c < 2; ++c) load[2 * node + c] += t.traction[c] * phi * length;
        }
      }
    }
    for (Index dof = 0; dof < size(); ++dof)
      if (fixed_[static_cast<std::size_t>(dof)]) load[dof] = 0;
    loadVectors_.push_back(std::move(load));
  }
}

void SpectralElementElasticity::addStiffnessProduct(const Real* x, Real* y, Real sign) const {
  const int n = settings_.order;
  const auto local = static_cast<Index>(localOffsets_.size());
  // plain buffers mapped for the product: no Eigen temporaries in the loop
  std::vector<Real> gathered(static_cast<std::size_t>(2 * local)), product(gathered.size());
  const Eigen::Map<const Vector> gatheredView(gathered.data(), 2 * local);
  Eigen::Map<Vector> productView(product.data(), 2 * local);
  const char* fixed = fixed_.data();
  for (Index ey = 0; ey < elements_[1]; ++ey)
    for (Index ex = 0; ex < elements_[0]; ++ex) {
      const Index base = ey * n * nodes_[0] + ex * n;
      for (Index l = 0; l < local; ++l) {
        const Index dof = 2 * (base + localOffsets_[static_cast<std::size_t>(l)]);
        gathered[static_cast<std::size_t>(2 * l)] = fixed[dof] ? 0.0 : x[dof];
        gathered[static_cast<std::size_t>(2 * l + 1)] = fixed[dof + 1] ? 0.0 : x[dof + 1];
      }
      productView.noalias() = elementStiffness_ * gatheredView;
      for (Index l = 0; l < local; ++l) {
        const Index dof = 2 * (base + localOffsets_[static_cast<std::size_t>(l)]);
        if (!fixed[dof]) y[dof] += sign * product[static_cast<std::size_t>(2 * l)];
        if (!fixed[dof + 1]) y[dof + 1] += sign * product[static_cast<std::size_t>(2 * l + 1)];
      }
    }
}

void SpectralElementElasticity::force(Real t, Vector& f) const {
  f.setZero(size());
  for (std::size_t k = 0; k < loadVectors_.size(); ++k) f += settings_.tractions[k].history(t) * loadVectors_[k];
}

void SpectralElementElasticity::residual(Real t, const Real* u, const Real* v, Real* r) const {
  Eigen::Map<Vector> out(r, size());
  out.setZero();
  for (std::size_t k = 0; k < loadVectors_.size(); ++k) out += settings_.tractions[k].history(t) * loadVectors_[k];
  addStiffnessProduct(u, r, -1.0);
  if (hasDamping_) out.array() -= damping_.array() * Eigen::Map<const Vector>(v, size()).array();
  for (Index dof = 0; dof < size(); ++dof)
    if (fixed_[static_cast<std::size_t>(dof)]) r[dof] = 0;
}

void SpectralElementElasticity::acceleration(Real t, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector> v,
                                             Eigen::Ref<Vector> a) {
  residual(t, u.data(), v.data(), a.data());
  a.array() /= mass_.array();
}

void SpectralElementElasticity::applyStiffness(const Vector& x, Vector& y) const {
  y.setZero(size());
  addStiffnessProduct(x.data(), y.data(), 1.0);
}

Real SpectralElementElasticity::kineticEnergy(const Vector& v) const {
  return 0.5 * (v.array().square() * mass_.array()).sum();
}

Real SpectralElementElasticity::strainEnergy(const Vector& u) const {
  Vector ku;
  applyStiffness(u, ku);
  Real sum = 0;
  for (Index dof = 0; dof < size(); ++dof)
    if (!fixed_[static_cast<std::size_t>(dof)]) sum += u[dof] * ku[dof];
  return 0.5 * sum;
}

Real SpectralElementElasticity::dampingPower(const Vector& v) const {
  if (!hasDamping_) return 0;
  return (v.array().square() * damping_.array()).sum();
}

Vector SpectralElementElasticity::stiffnessAbsoluteRowSums() const {
  const int n = settings_.order;
  const auto local = static_cast<Index>(localOffsets_.size());
  const Eigen::MatrixXd absolute = elementStiffness_.cwiseAbs();
  Vector sums = Vector::Zero(size());
  std::vector<Index> dofs(static_cast<std::size_t>(2 * local));
  for (Index ey = 0; ey < elements_[1]; ++ey)
    for (Index ex = 0; ex < elements_[0]; ++ex) {
      const Index base = ey * n * nodes_[0] + ex * n;
      for (Index l = 0; l < local; ++l)
        for (int c = 0; c < 2; ++c)
          dofs[static_cast<std::size_t>(2 * l + c)] = 2 * (base + localOffsets_[static_cast<std::size_t>(l)]) + c;
      for (Index i = 0; i < 2 * local; ++i) {
        const Index row = dofs[static_cast<std::size_t>(i)];
        if (fixed_[static_cast<std::size_t>(row)]) continue;
        Real s = 0;
        for (Index j = 0; j < 2 * local; ++j)
          if (!fixed_[static_cast<std::size_t>(dofs[static_cast<std::size_t>(j)])]) s += absolute(i, j);
        sums[row] += s;
      }
    }
  return sums;
}

std::unique_ptr<CentredDampingSolve> SpectralElementElasticity::centredDamping(
    Real dt, const std::vector<Index>& prescribedDofs) const {
  return std::make_unique<SpectralElementCentredDamping>(*this, dt, prescribedDofs);
}

Vec2 SpectralElementElasticity::nodePosition(Index node) const {
  return Vec2(axisCoordinates_[0][static_cast<std::size_t>(node % nodes_[0])],
              axisCoordinates_[1][static_cast<std::size_t>(node / nodes_[0])]);
}

Index SpectralElementElasticity::nodeAt(const Vec2& x) const {
  const Real tolerance = 1e-9 * settings_.elementSize;
  std::array<Index, 2> index{-1, -1};
  for (int axis = 0; axis < 2; ++axis) {
    const std::vector<Real>& c = axisCoordinates_[static_cast<std::size_t>(axis)];
    for (std::size_t k = 0; k < c.size(); ++k)
      if (std::abs(c[k] - x[axis]) <= tolerance) index[static_cast<std::size_t>(axis)] = static_cast<Index>(k);
    if (index[static_cast<std::size_t>(axis)] < 0) return -1;
  }
  return index[1] * nodes_[0] + index[0];
}

ParticleSet<2> SpectralElementElasticity::nodeParticles() const {
  ParticleSet<2> particles;
  particles.reserve(nodeCount());
  const Real rho = settings_.material.density();
  for (Index node = 0; node < nodeCount(); ++node) {
    const Index i = node % nodes_[0], j = node / nodes_[0];
    std::uint8_t faces = 0;
    if (i == 0) faces |= faceBit(BoxFace::MinusX);
    if (i == nodes_[0] - 1) faces |= faceBit(BoxFace::PlusX);
    if (j == 0) faces |= faceBit(BoxFace::MinusY);
    if (j == nodes_[1] - 1) faces |= faceBit(BoxFace::PlusY);
    particles.add(nodePosition(node), mass_[2 * node] / rho, ParticleKind::Physical, faces);
  }
  return particles;
}

}  // namespace mfwave
