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


// Calls f(index) for every multi-index below `extent`, axis 0 fastest (the node numbering's order).
template <int D, class F>
void forEachIndex(const std::array<Index, D>& extent, F&& f) {
  Index total = 1;
  for (int d = 0; d < D; ++d) total *= extent[static_cast<std::size_t>(d)];
  std::array<Index, D> index{};
  for (Index k = 0; k < total; ++k) {
    Index rest = k;
    for (int d = 0; d < D; ++d) {
      index[static_cast<std::size_t>(d)] = rest % extent[static_cast<std::size_t>(d)];
      rest /= extent[static_cast<std::size_t>(d)];
    }
    f(index);
  }
}

// The Lagrange basis of the nodes at x in [-1, 1].
Real lagrange(const std::vector<Real>& nodes, Real x, int j) {
  Real value = 1;
  for (std::size_t k = 0; k < nodes.size(); ++k)
    if (static_cast<int>(k) != j) value *= (x - nodes[k]) / (nodes[static_cast<std::size_t>(j)] - nodes[k]);
  return value;
}

// (M + dt/2 C) a = f - K u - C vHalf with a diagonal M and C (Ding-Long-Wu eq. (32)): a division
// per unknown; prescribed unknowns take their known accelerations (a diagonal matrix does not
// couple them to the others).
template <int D>
class SpectralElementCentredDamping : public CentredDampingSolve {
 public:
  SpectralElementCentredDamping(const SpectralElementElasticity<D>& system, Real dt, std::vector<Index> prescribedDofs)
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
  const SpectralElementElasticity<D>& system_;
  std::vector<Index> prescribed_;
  Vector inverse_;
};

}  // namespace

Index wholeElements(Real length, Real h) {
  const Real count = length / h;
  const Real rounded = std::round(count);
  if (rounded < 1 || std::abs(count - rounded) > 1e-9 * std::max<Real>(1, count)) return -1;
  return static_cast<Index>(rounded);
}

template <int D>
SpectralElementElasticity<D>::SpectralElementElasticity(SpectralElementSettings<D> settings)
    : settings_(std::move(settings)) {
  const int n = settings_.order;
  if (n < 1 || n > 8) throw InputError("order", "the spectral-element order N must be 1 .. 8, got " + std::to_string(n));
  const Real h = settings_.elementSize;
  if (!(h > 0)) throw InputError("elementSize", "must be positive");
  for (int axis = 0; axis < D; ++axis) {
    const Real length = settings_.upper[axis] - settings_.lower[axis];
    const Index count = wholeElements(length, h);
    if (count < 0) {
      std::ostringstream problem;
      problem << "the side " << length << " along axis " << axis << " is not a whole number of elements of size " << h;
      throw InputError("elementSize", problem.str());
    }
    const auto a = static_cast<std::size_t>(axis);
    const bool lowerPeriodic = settings_.faces[2 * a] == SpectralElementFace::Periodic;
    const bool upperPeriodic = settings_.faces[2 * a + 1] == SpectralElementFace::Periodic;
    if (lowerPeriodic != upperPeriodic)
      throw InputError("faces", "axis " + std::to_string(axis) + " is periodic on one face only (both or neither)");
    periodic_[a] = lowerPeriodic;
    // Elements of one parity colour share no node (addStiffnessProduct); around a periodic axis the
    // first and last elements are neighbours, so their parities must differ (or be the one element).
    if (periodic_[a] && count > 1 && count % 2 != 0)
      throw InputError("elementSize", "the periodic axis " + std::to_string(axis) + " has " + std::to_string(count) +
                                          " elements: an even number (or one) is needed");
    elements_[a] = count;
    nodes_[a] = periodic_[a] ? count * n : count * n + 1;
  }
  const QuadratureRule rule = gaussLobattoLegendre(n);
  gllNodes_ = rule.nodes;
  gllWeights_ = rule.weights;
  for (int axis = 0; axis < D; ++axis) {
    std::vector<Real>& coordinates = axisCoordinates_[static_cast<std::size_t>(axis)];
    coordinates.resize(static_cast<std::size_t>(nodes_[static_cast<std::size_t>(axis)]));
    for (Index e = 0; e < elements_[static_cast<std::size_t>(axis)]; ++e)
      for (int a = 0; a <= n; ++a) {
        // along a periodic axis the last element's far line is the first node line: no entry of its own
        const auto at = static_cast<std::size_t>(e * n + a);
        if (at < coordinates.size())
          coordinates[at] =
              settings_.lower[axis] + h * (static_cast<Real>(e) + 0.5 * (1 + gllNodes_[static_cast<std::size_t>(a)]));
      }
    if (!periodic_[static_cast<std::size_t>(axis)]) coordinates.back() = settings_.upper[axis];
  }
  buildReferenceData();
  // Materials: one, or one per element from its centre.
  if (settings_.regionMaterials.empty()) {
    materials_ = {settings_.material};
  } else {
    if (!settings_.materialAt) throw InputError("material", "regions without a rule giving each element its material");
    materials_ = settings_.regionMaterials;
    elementMaterial_.resize(static_cast<std::size_t>(elementCount()));
    for (Index e = 0; e < elementCount(); ++e) {
      const int m = settings_.materialAt(elementCentre(e));
      if (m < 0 || m >= static_cast<int>(materials_.size()))
        throw InputError("material", "element " + std::to_string(e) + " lies in no region of a material");
      elementMaterial_[static_cast<std::size_t>(e)] = m;
    }
  }
  // In 2-D the element matrix is small (50 square for N = 4) and its dense product, vectorised by
  // Eigen, measured about 1.3 times faster than the sum-factorised one (SpectralElement3dTest): it is
  // cached, assembled from the sum-factorised product, so both dimensions share the one kernel. In
  // 3-D (375 square) sum factorisation is about 5 times faster and nothing dense is kept.
  if (D == 2)
    for (int m = 0; m < static_cast<int>(materials_.size()); ++m) denseElements_.push_back(elementStiffness(m));
  fixed_.assign(static_cast<std::size_t>(size()), 0);
  for (int face = 0; face < 2 * D; ++face) {
    if (settings_.faces[static_cast<std::size_t>(face)] != SpectralElementFace::Fixed) continue;
    const auto axis = static_cast<std::size_t>(faceAxis(face));
    const Index line = faceSign(face) < 0 ? 0 : nodes_[axis] - 1;
    forEachIndex<D>(nodes_, [&](const Nodes& index) {
      if (index[axis] != line) return;
      Index node = 0;
      for (int d = D - 1; d >= 0; --d) node = node * nodes_[static_cast<std::size_t>(d)] + index[static_cast<std::size_t>(d)];
      for (int c = 0; c < D; ++c) fixed_[static_cast<std::size_t>(D * node + c)] = 1;
    });
  }
  buildMassAndDamping();
  buildLoads();
}

template <int D>
Index SpectralElementElasticity<D>::nodeCount() const {
  Index count = 1;
  for (const Index k : nodes_) count *= k;
  return count;
}

template <int D>
Index SpectralElementElasticity<D>::elementCount() const {
  Index count = 1;
  for (const Index k : elements_) count *= k;
  return count;
}

// The reference element's data for the sum-factorised product (Deville, Fischer & Mund 2002,
// section 4.3): the scaled derivative matrix, the weights times the Jacobian per point, each local
// node's offset in the global numbering and its index along each axis.
template <int D>
void SpectralElementElasticity<D>::buildReferenceData() {
  const int points = settings_.order + 1;
  const Real h = settings_.elementSize;
  pointsPerElement_ = 1;
  for (int d = 0; d < D; ++d) pointsPerElement_ *= points;
  const Eigen::MatrixXd derivative = lagrangeDerivativeMatrix(gllNodes_);
  derivative_.resize(static_cast<std::size_t>(points * points));
  for (int i = 0; i < points; ++i)
    for (int j = 0; j < points; ++j) derivative_[static_cast<std::size_t>(i * points + j)] = 2 / h * derivative(i, j);
  const Real jacobian = std::pow(0.5 * h, D);
  Nodes extent{};
  extent.fill(points);
  std::array<Index, D> globalStride{};
  for (int d = 0; d < D; ++d)
    globalStride[static_cast<std::size_t>(d)] = d == 0 ? 1 : globalStride[static_cast<std::size_t>(d - 1)] * nodes_[static_cast<std::size_t>(d - 1)];
  localOffsets_.clear();
  pointWeights_.clear();
  for (auto& v : lineIndex_) v.clear();
  forEachIndex<D>(extent, [&](const Nodes& local) {
    Index offset = 0;
    Real weight = jacobian;
    for (int d = 0; d < D; ++d) {
      const auto k = static_cast<std::size_t>(d);
      offset += local[k] * globalStride[k];
      weight *= gllWeights_[static_cast<std::size_t>(local[k])];
    }
    localOffsets_.push_back(offset);
    pointWeights_.push_back(weight);
    for (int d = 0; d < D; ++d) {
      const auto k = static_cast<std::size_t>(d);
      lineIndex_[k].push_back(static_cast<int>(local[k]));
    }
  });
}

namespace {

// out (+)= the 1-D matrix m (or its transpose) applied along the axis of stride `stride` of a
// tensor of `count` points, P per axis (Deville, Fischer & Mund 2002, section 4.3: each GLL line
// of the element independently). Along axis 0 (stride 1) each output is a dot product; along the
// others the innermost loop runs over the contiguous points below the axis.
// P = points is a template argument so the short loops over a line unroll (orders 1 .. 8 are
// instantiated; applyAlongAxisFor dispatches).
template <int P>
void applyAlongAxis(const Real* m, Index count, Index stride, bool transpose, bool accumulate, const Real* in,
                    Real* out) {
  constexpr int points = P;
  const Index block = points * stride;
  const Index rowStep = transpose ? 1 : points, columnStep = transpose ? points : 1;
  if (stride == 1) {
    for (Index base = 0; base < count; base += block)
      for (int i = 0; i < points; ++i) {
        const Real* row = m + i * rowStep;
        Real sum = 0;
        for (int k = 0; k < points; ++k) sum += row[k * columnStep] * in[base + k];
        out[base + i] = accumulate ? out[base + i] + sum : sum;
      }
    return;
  }
  for (Index base = 0; base < count; base += block)
    for (int i = 0; i < points; ++i) {
      Real* target = out + base + i * stride;
      if (!accumulate)
        for (Index inner = 0; inner < stride; ++inner) target[inner] = 0;
      const Real* row = m + i * rowStep;
      for (int k = 0; k < points; ++k) {
        const Real coefficient = row[k * columnStep];
        const Real* source = in + base + k * stride;
        for (Index inner = 0; inner < stride; ++inner) target[inner] += coefficient * source[inner];
      }
    }
}

void applyAlongAxisFor(int points, const Real* m, Index count, Index stride, bool transpose, bool accumulate,
                       const Real* in, Real* out) {
  switch (points) {
    case 2: applyAlongAxis<2>(m, count, stride, transpose, accumulate, in, out); return;
    case 3: applyAlongAxis<3>(m, count, stride, transpose, accumulate, in, out); return;
    case 4: applyAlongAxis<4>(m, count, stride, transpose, accumulate, in, out); return;
    case 5: applyAlongAxis<5>(m, count, stride, transpose, accumulate, in, out); return;
    case 6: applyAlongAxis<6>(m, count, stride, transpose, accumulate, in, out); return;
    case 7: applyAlongAxis<7>(m, count, stride, transpose, accumulate, in, out); return;
    case 8: applyAlongAxis<8>(m, count, stride, transpose, accumulate, in, out); return;
    case 9: applyAlongAxis<9>(m, count, stride, transpose, accumulate, in, out); return;
    default: throw InputError("order", "the spectral-element order N must be 1 .. 8");
  }
}

}  // namespace

// K_e x = sum over GLL points of B^T D B x w J (Komatitsch & Tromp 1999, eq. 19 ff.), evaluated by
// sum factorisation (Deville, Fischer & Mund 2002): the gradient of each component along axis d at
// the points is the derivative matrix applied along the GLL lines of that axis; the weighted
// stress goes back through the transposed matrix. x and y are planar here (component c at
// c (N + 1)^D + l), which keeps the lines contiguous.
template <int D>
void SpectralElementElasticity<D>::planarElementProduct(const Real* x, Real* y, const Material& material) const {
  const int points = settings_.order + 1;
  const Index count = pointsPerElement_;
  const Real lambda = material.lambda(), mu = material.mu();
  thread_local std::vector<Real> work;
  work.resize(static_cast<std::size_t>(D * D * count));
  Real* field = work.data();  // [(c D + d) count + q]: first du_c/dx_d, then w J sigma_cd
  const Real* dm = derivative_.data();
  for (int c = 0; c < D; ++c) {
    Index stride = 1;
    for (int d = 0; d < D; ++d, stride *= points)
      applyAlongAxisFor(points, dm, count, stride, false, false, x + c * count, field + (c * D + d) * count);
  }
  const Real* weights = pointWeights_.data();
  for (Index q = 0; q < count; ++q) {
    Real g[D][D];
    Real trace = 0;
    for (int c = 0; c < D; ++c) {
      for (int d = 0; d < D; ++d) g[c][d] = field[(c * D + d) * count + q];
      trace += g[c][c];
    }
    const Real w = weights[q];
    for (int c = 0; c < D; ++c)
      for (int d = 0; d < D; ++d)
        field[(c * D + d) * count + q] = w * (mu * (g[c][d] + g[d][c]) + (c == d ? lambda * trace : 0.0));
  }
  for (int c = 0; c < D; ++c) {
    Index stride = 1;
    for (int d = 0; d < D; ++d, stride *= points)
      applyAlongAxisFor(points, dm, count, stride, true, d > 0, field + (c * D + d) * count, y + c * count);
  }
}

template <int D>
void SpectralElementElasticity<D>::elementProduct(const Real* x, Real* y, int material) const {
  const Index count = pointsPerElement_;
  thread_local std::vector<Real> planarX, planarY;
  planarX.resize(static_cast<std::size_t>(D * count));
  planarY.resize(planarX.size());
  for (Index l = 0; l < count; ++l)
    for (int c = 0; c < D; ++c) planarX[static_cast<std::size_t>(c * count + l)] = x[D * l + c];
  planarElementProduct(planarX.data(), planarY.data(), materials_.at(static_cast<std::size_t>(material)));
  for (Index l = 0; l < count; ++l)
    for (int c = 0; c < D; ++c) y[D * l + c] = planarY[static_cast<std::size_t>(c * count + l)];
}

template <int D>
Vec<D> SpectralElementElasticity<D>::elementCentre(Index e) const {
  Vec<D> x;
  for (int d = 0; d < D; ++d) {
    const auto k = static_cast<std::size_t>(d);
    x[d] = settings_.lower[d] + (static_cast<Real>(e % elements_[k]) + 0.5) * settings_.elementSize;
    e /= elements_[k];
  }
  return x;
}

template <int D>
Eigen::MatrixXd SpectralElementElasticity<D>::elementStiffness(int material) const {
  const Index local = D * pointsPerElement_;
  Eigen::MatrixXd k(local, local);
  Vector unit = Vector::Zero(local), column(local);
  for (Index j = 0; j < local; ++j) {
    unit[j] = 1;
    elementProduct(unit.data(), column.data(), material);
    k.col(j) = column;
    unit[j] = 0;
  }
  return k;
}

template <int D>
Index SpectralElementElasticity<D>::elementBase(Index e) const {
  Index base = 0, stride = 1;
  for (int d = 0; d < D; ++d) {
    const auto k = static_cast<std::size_t>(d);
    base += (e % elements_[k]) * settings_.order * stride;
    e /= elements_[k];
    stride *= nodes_[k];
  }
  return base;
}

template <int D>
void SpectralElementElasticity<D>::elementNodes(Index e, Index* nodes) const {
  const Index base = elementBase(e);
  for (Index l = 0; l < pointsPerElement_; ++l) nodes[l] = base + localOffsets_[static_cast<std::size_t>(l)];
  Index stride = 1;
  for (int d = 0; d < D; ++d) {
    const auto k = static_cast<std::size_t>(d);
    const Index along = e % elements_[k];
    e /= elements_[k];
    // the last element's far line is the axis' first: one axis length back
    if (periodic_[k] && along == elements_[k] - 1)
      for (Index l = 0; l < pointsPerElement_; ++l)
        if (lineIndex_[k][static_cast<std::size_t>(l)] == settings_.order) nodes[l] -= nodes_[k] * stride;
    stride *= nodes_[k];
  }
}

template <int D>
void SpectralElementElasticity<D>::buildMassAndDamping() {
  const int n = settings_.order;
  const Real h = settings_.elementSize;
  // Komatitsch & Tromp 1999: GLL quadrature on the GLL nodes makes M diagonal, rho w_a w_b (w_c) J,
  // rho the element's.
  mass_ = Vector::Zero(size());
  volume_ = Vector::Zero(nodeCount());
  std::vector<Index> nodes(static_cast<std::size_t>(pointsPerElement_));
  for (Index e = 0; e < elementCount(); ++e) {
    const Real rho = materials_[static_cast<std::size_t>(elementMaterial(e))].density();
    elementNodes(e, nodes.data());
    for (Index l = 0; l < pointsPerElement_; ++l) {
      const Index node = nodes[static_cast<std::size_t>(l)];
      volume_[node] += pointWeights_[static_cast<std::size_t>(l)];
      for (int c = 0; c < D; ++c) mass_[D * node + c] += rho * pointWeights_[static_cast<std::size_t>(l)];
    }
  }
  // Lysmer & Kuhlemeyer 1969 dashpots, integrated over the face by the same GLL rule (diagonal C):
  // rho c_p on the normal component, rho c_s on the tangential ones, per unit area.
  damping_ = Vector::Zero(size());
  const Real faceJacobian = std::pow(0.5 * h, D - 1);
  for (int face = 0; face < 2 * D; ++face) {
    if (settings_.faces[static_cast<std::size_t>(face)] != SpectralElementFace::Absorbing) continue;
    hasDamping_ = true;
    const int axis = faceAxis(face);
    const auto a = static_cast<std::size_t>(axis);
    const Index line = faceSign(face) < 0 ? 0 : nodes_[a] - 1;
    const int localLine = faceSign(face) < 0 ? 0 : n;
    for (Index e = 0; e < elementCount(); ++e) {
      const Material& material = materials_[static_cast<std::size_t>(elementMaterial(e))];
      const Real rho = material.density(), cp = material.pWaveSpeed(), cs = material.sWaveSpeed();
      elementNodes(e, nodes.data());
      for (Index l = 0; l < pointsPerElement_; ++l) {
        if (lineIndex_[a][static_cast<std::size_t>(l)] != localLine) continue;
        const Index node = nodes[static_cast<std::size_t>(l)];
        // the node's index along the axis: only the elements touching the face contribute
        Index rest = node;
        for (int d = 0; d < axis; ++d) rest /= nodes_[static_cast<std::size_t>(d)];
        if (rest % nodes_[a] != line) continue;
        Real area = faceJacobian;
        for (int d = 0; d < D; ++d)
          if (d != axis)
            area *= gllWeights_[static_cast<std::size_t>(lineIndex_[static_cast<std::size_t>(d)][static_cast<std::size_t>(l)])];
        for (int c = 0; c < D; ++c) damping_[D * node + c] += rho * (c == axis ? cp : cs) * area;
      }
    }
  }
  for (Index dof = 0; dof < size(); ++dof)
    if (fixed_[static_cast<std::size_t>(dof)]) damping_[dof] = 0;
}

// f_i = integral over the face of T phi_i dA, exactly: on each face element the loaded part (a
// box over the tangential axes) is integrated by tensor (N + 1)-point Gauss-Legendre, exact for
// the degree-N basis restricted to the face. When an edge of the rectangle falls inside an element
// the load's jump is integrated exactly too, though the degree-N trace cannot follow it (the
// coarse lamb2d case at spacing 0.25, N = 4: elements of side 1, strip ends at +-0.5; in lamb3d's
// 7-wide block the loaded square is one element's face there).
template <int D>
void SpectralElementElasticity<D>::buildLoads() {
  const int n = settings_.order;
  const Real h = settings_.elementSize;
  const QuadratureRule gauss = gaussLegendre(n + 1);
  const Real tolerance = 1e-9 * h;
  for (const SpectralElementTraction<D>& t : settings_.tractions) {
    if (t.face < 0 || t.face >= 2 * D) throw InputError("traction", "face must be 0 .. " + std::to_string(2 * D - 1));
    if (!t.history) throw InputError("traction", "needs a time function");
    const int axis = faceAxis(t.face);
    const auto a = static_cast<std::size_t>(axis);
    if (periodic_[a]) throw InputError("traction", "face " + std::to_string(t.face) + " is periodic: it is no boundary");
    for (int d = 0; d < D; ++d) {
      if (d == axis) continue;
      const Real start = t.centre[d] - t.halfWidth[d], end = t.centre[d] + t.halfWidth[d];
      if (!(t.halfWidth[d] > 0) || start < settings_.lower[d] - tolerance || end > settings_.upper[d] + tolerance) {
        std::ostringstream problem;
        problem << "the loaded range [" << start << ", " << end << "] along " << axisName(d)
                << " must have a positive width and lie on the face [" << settings_.lower[d] << ", "
                << settings_.upper[d] << "]";
        throw InputError("traction", problem.str());
      }
    }
    const Index line = faceSign(t.face) < 0 ? 0 : nodes_[a] - 1;
    const int localLine = faceSign(t.face) < 0 ? 0 : n;
    Vector load = Vector::Zero(size());
    // the face's elements: every element index along the tangential axes, the face's along the normal
    Nodes faceElements = elements_;
    faceElements[a] = 1;
    forEachIndex<D>(faceElements, [&](Nodes element) {
      element[a] = line == 0 ? 0 : elements_[a] - 1;
      std::array<Real, D> from{}, to{}, origin{};
      for (int d = 0; d < D; ++d) {
        const auto k = static_cast<std::size_t>(d);
        if (d == axis) continue;
        origin[k] = settings_.lower[d] + static_cast<Real>(element[k]) * h;
        from[k] = std::max(t.centre[d] - t.halfWidth[d], origin[k]);
        to[k] = std::min(t.centre[d] + t.halfWidth[d], origin[k] + h);
        if (to[k] - from[k] <= tolerance) return;
      }
      Index linear = 0;
      for (int d = D - 1; d >= 0; --d)
        linear = linear * elements_[static_cast<std::size_t>(d)] + element[static_cast<std::size_t>(d)];
      std::vector<Index> nodes(static_cast<std::size_t>(pointsPerElement_));
      elementNodes(linear, nodes.data());
      // tensor Gauss points over the loaded box (one point along the normal axis)
      Nodes gaussExtent{};
      gaussExtent.fill(static_cast<Index>(gauss.nodes.size()));
      gaussExtent[a] = 1;
      forEachIndex<D>(gaussExtent, [&](const Nodes& g) {
        std::array<Real, D> xi{};
        Real area = 1;
        for (int d = 0; d < D; ++d) {
          const auto k = static_cast<std::size_t>(d);
          if (d == axis) continue;
          const auto gk = static_cast<std::size_t>(g[k]);
          const Real x = 0.5 * (from[k] + to[k]) + 0.5 * (to[k] - from[k]) * gauss.nodes[gk];
          xi[k] = 2 * (x - origin[k]) / h - 1;
          area *= 0.5 * (to[k] - from[k]) * gauss.weights[gk];
        }
        for (Index l = 0; l < pointsPerElement_; ++l) {
          if (lineIndex_[a][static_cast<std::size_t>(l)] != localLine) continue;
          Real phi = area;
          for (int d = 0; d < D; ++d)
            if (d != axis)
              phi *= lagrange(gllNodes_, xi[static_cast<std::size_t>(d)],
                              lineIndex_[static_cast<std::size_t>(d)][static_cast<std::size_t>(l)]);
          const Index node = nodes[static_cast<std::size_t>(l)];
          for (int c = 0; c < D; ++c) load[D * node + c] += t.traction[c] * phi;
        }
      });
    });
    for (Index dof = 0; dof < size(); ++dof)
      if (fixed_[static_cast<std::size_t>(dof)]) load[dof] = 0;
    loadVectors_.push_back(std::move(load));
  }
}

template <int D>
int SpectralElementElasticity<D>::elementColour(Index e) const {
  int colour = 0;
  for (int d = 0; d < D; ++d) {
    const auto k = static_cast<std::size_t>(d);
    colour |= static_cast<int>((e % elements_[k]) % 2) << d;
    e /= elements_[k];
  }
  return colour;
}

template <int D>
void SpectralElementElasticity<D>::addElementProduct(Index e, const Real* x, Real* y, Real sign, Real* gathered,
                                                     Real* product, Index* nodes) const {
  const Index local = pointsPerElement_;
  const char* fixed = fixed_.data();
  elementNodes(e, nodes);
  const int material = elementMaterial(e);
  if (!denseElements_.empty()) {  // the cached K_e (interleaved local dofs)
    for (Index l = 0; l < local; ++l) {
      const Index dof = D * nodes[l];
      for (int c = 0; c < D; ++c) gathered[D * l + c] = fixed[dof + c] ? 0.0 : x[dof + c];
    }
    Eigen::Map<Vector>(product, D * local).noalias() =
        denseElements_[static_cast<std::size_t>(material)] * Eigen::Map<const Vector>(gathered, D * local);
    for (Index l = 0; l < local; ++l) {
      const Index dof = D * nodes[l];
      for (int c = 0; c < D; ++c)
        if (!fixed[dof + c]) y[dof + c] += sign * product[D * l + c];
    }
    return;
  }
  for (Index l = 0; l < local; ++l) {
    const Index dof = D * nodes[l];
    for (int c = 0; c < D; ++c) gathered[c * local + l] = fixed[dof + c] ? 0.0 : x[dof + c];
  }
  planarElementProduct(gathered, product, materials_[static_cast<std::size_t>(material)]);
  for (Index l = 0; l < local; ++l) {
    const Index dof = D * nodes[l];
    for (int c = 0; c < D; ++c)
      if (!fixed[dof + c]) y[dof + c] += sign * product[c * local + l];
  }
}

template <int D>
void SpectralElementElasticity<D>::addStiffnessProduct(const Real* x, Real* y, Real sign) const {
  // Elements coloured by the parity of their index along each axis: two elements of one colour are
  // two or more elements apart along some axis, so they share no node, and every unknown receives
  // at most one contribution per colour. The colours run in a fixed order, so each unknown's sum is
  // formed in the same order on any number of threads: the product is bitwise thread-independent.
  const Index count = elementCount();
  const auto buffer = static_cast<std::size_t>(D * pointsPerElement_);
  for (int colour = 0; colour < (1 << D); ++colour) {
#pragma omp parallel if (count >= kParallelElements)
    {
      std::vector<Real> gathered(buffer), product(buffer);
      std::vector<Index> nodes(static_cast<std::size_t>(pointsPerElement_));
#pragma omp for schedule(static)
      for (Index e = 0; e < count; ++e)
        if (elementColour(e) == colour)
          addElementProduct(e, x, y, sign, gathered.data(), product.data(), nodes.data());
    }
  }
}

template <int D>
void SpectralElementElasticity<D>::force(Real t, Vector& f) const {
  f.setZero(size());
  for (std::size_t k = 0; k < loadVectors_.size(); ++k) f += settings_.tractions[k].history(t) * loadVectors_[k];
}

template <int D>
void SpectralElementElasticity<D>::residual(Real t, const Real* u, const Real* v, Real* r) const {
  Eigen::Map<Vector> out(r, size());
  out.setZero();
  for (std::size_t k = 0; k < loadVectors_.size(); ++k) out += settings_.tractions[k].history(t) * loadVectors_[k];
  addStiffnessProduct(u, r, -1.0);
  if (hasDamping_) out.array() -= damping_.array() * Eigen::Map<const Vector>(v, size()).array();
  for (Index dof = 0; dof < size(); ++dof)
    if (fixed_[static_cast<std::size_t>(dof)]) r[dof] = 0;
}

template <int D>
void SpectralElementElasticity<D>::acceleration(Real t, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector> v,
                                                Eigen::Ref<Vector> a) {
  residual(t, u.data(), v.data(), a.data());
  a.array() /= mass_.array();
}

template <int D>
void SpectralElementElasticity<D>::applyStiffness(const Vector& x, Vector& y) const {
  y.setZero(size());
  addStiffnessProduct(x.data(), y.data(), 1.0);
}

template <int D>
Real SpectralElementElasticity<D>::kineticEnergy(const Vector& v) const {
  return 0.5 * (v.array().square() * mass_.array()).sum();
}

template <int D>
Real SpectralElementElasticity<D>::strainEnergy(const Vector& u) const {
  Vector ku;
  applyStiffness(u, ku);
  Real sum = 0;
  for (Index dof = 0; dof < size(); ++dof)
    if (!fixed_[static_cast<std::size_t>(dof)]) sum += u[dof] * ku[dof];
  return 0.5 * sum;
}

template <int D>
Real SpectralElementElasticity<D>::dampingPower(const Vector& v) const {
  if (!hasDamping_) return 0;
  return (v.array().square() * damping_.array()).sum();
}

// Element by element with |K_e|: the dense matrix once; an element without fixed unknowns adds
// its precomputed row sums, one with them sums the unmasked columns.
template <int D>
Vector SpectralElementElasticity<D>::stiffnessAbsoluteRowSums() const {
  const Index local = D * pointsPerElement_;
  std::vector<Eigen::MatrixXd> absolutes;
  std::vector<Vector> rowSumsOf;
  for (int m = 0; m < static_cast<int>(materials_.size()); ++m) {
    absolutes.push_back(elementStiffness(m).cwiseAbs());
    rowSumsOf.push_back(absolutes.back().rowwise().sum());
  }
  Vector sums = Vector::Zero(size());
  std::vector<Index> dofs(static_cast<std::size_t>(local)), nodes(static_cast<std::size_t>(pointsPerElement_));
  for (Index e = 0; e < elementCount(); ++e) {
    const Eigen::MatrixXd& absolute = absolutes[static_cast<std::size_t>(elementMaterial(e))];
    const Vector& rowSums = rowSumsOf[static_cast<std::size_t>(elementMaterial(e))];
    elementNodes(e, nodes.data());
    bool anyFixed = false;
    for (Index l = 0; l < pointsPerElement_; ++l)
      for (int c = 0; c < D; ++c) {
        const Index dof = D * nodes[static_cast<std::size_t>(l)] + c;
        dofs[static_cast<std::size_t>(D * l + c)] = dof;
        anyFixed = anyFixed || fixed_[static_cast<std::size_t>(dof)] != 0;
      }
    for (Index i = 0; i < local; ++i) {
      const Index row = dofs[static_cast<std::size_t>(i)];
      if (fixed_[static_cast<std::size_t>(row)]) continue;
      if (!anyFixed) {
        sums[row] += rowSums[i];
        continue;
      }
      Real s = 0;
      for (Index j = 0; j < local; ++j)
        if (!fixed_[static_cast<std::size_t>(dofs[static_cast<std::size_t>(j)])]) s += absolute(i, j);
      sums[row] += s;
    }
  }
  return sums;
}

template <int D>
std::unique_ptr<CentredDampingSolve> SpectralElementElasticity<D>::centredDamping(
    Real dt, const std::vector<Index>& prescribedDofs) const {
  return std::make_unique<SpectralElementCentredDamping<D>>(*this, dt, prescribedDofs);
}

template <int D>
Vec<D> SpectralElementElasticity<D>::nodePosition(Index node) const {
  Vec<D> x;
  for (int d = 0; d < D; ++d) {
    const auto k = static_cast<std::size_t>(d);
    x[d] = axisCoordinates_[k][static_cast<std::size_t>(node % nodes_[k])];
    node /= nodes_[k];
  }
  return x;
}

template <int D>
Index SpectralElementElasticity<D>::nodeAt(const Vec<D>& x) const {
  const Real tolerance = 1e-9 * settings_.elementSize;
  Index node = 0;
  for (int axis = D - 1; axis >= 0; --axis) {
    const std::vector<Real>& c = axisCoordinates_[static_cast<std::size_t>(axis)];
    Index index = -1;
    for (std::size_t k = 0; k < c.size(); ++k)
      if (std::abs(c[k] - x[axis]) <= tolerance) index = static_cast<Index>(k);
    if (index < 0) return -1;
    node = node * nodes_[static_cast<std::size_t>(axis)] + index;
  }
  return node;
}

template <int D>
ParticleSet<D> SpectralElementElasticity<D>::nodeParticles() const {
  ParticleSet<D> particles;
  particles.reserve(nodeCount());
  for (Index node = 0; node < nodeCount(); ++node) {
    std::uint8_t faces = 0;
    Index rest = node;
    for (int d = 0; d < D; ++d) {
      const Index i = rest % nodes_[static_cast<std::size_t>(d)];
      rest /= nodes_[static_cast<std::size_t>(d)];
      if (periodic_[static_cast<std::size_t>(d)]) continue;  // no face along a periodic axis
      if (i == 0) faces |= faceBit(2 * d);
      if (i == nodes_[static_cast<std::size_t>(d)] - 1) faces |= faceBit(2 * d + 1);
    }
    particles.add(nodePosition(node), volume_[node], ParticleKind::Physical, faces);
  }
  return particles;
}

template class SpectralElementElasticity<2>;
template class SpectralElementElasticity<3>;

}  // namespace mfwave
