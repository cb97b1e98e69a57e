#include "methods/collocation/ShapeFunctionMatrix.hpp"

#include <exception>
#include <limits>
#include <string>

#include "core/Error.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace mfwave {

namespace {

template <int D>
int checkedDerivatives(const std::vector<ShapeDerivative>& derivatives) {
  int highest = 0;
  for (const ShapeDerivative& d : derivatives) {
    const bool axesValid = d.axis1 >= 0 && d.axis1 < D && d.axis2 >= 0 && d.axis2 < D;
    if (d.order < 0 || d.order > 2 || !axesValid) {
      throw InputError("method.derivative", "derivative of order " + std::to_string(d.order) + " along axes (" +
                                                std::to_string(d.axis1) + ", " + std::to_string(d.axis2) +
                                                ") is not one of: value, d/dx_j, d2/dx_j dx_k with j, k in 0.." +
                                                std::to_string(D - 1));
    }
    highest = std::max(highest, d.order);
  }
  return highest;
}

template <int D>
Real entry(const ShapeFunctionValues<D>& values, std::size_t k, const ShapeDerivative& d) {
  switch (d.order) {
    case 0:
      return values.value[k];
    case 1:
      return values.gradient[k][d.axis1];
    default:
      return values.hessian[k](d.axis1, d.axis2);
  }
}

int threadCount() {
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}

int threadNumber() {
#ifdef _OPENMP
  return omp_get_thread_num();
#else
  return 0;
#endif
}

// Evaluates the shape functions at every point in parallel and hands each result to
// rowSink(thread, row, values). Exceptions stop the thread that meets them and are rethrown
// afterwards, the one of the lowest row first (each thread walks its rows in increasing order).
template <int D, class RowSink>
void forEachRow(const ShapeFunctions<D>& shapes, const std::vector<Vec<D>>& points, int derivatives, int threads,
                RowSink&& rowSink) {
  const auto count = static_cast<Index>(points.size());
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(threads));
  std::vector<Index> errorRow(static_cast<std::size_t>(threads), count);
#pragma omp parallel num_threads(threads)
  {
    ShapeFunctionValues<D> values;
    const auto t = static_cast<std::size_t>(threadNumber());
#pragma omp for schedule(static)
    for (Index row = 0; row < count; ++row) {
      if (errorRow[t] < count) continue;
      try {
        shapes.evaluate(points[static_cast<std::size_t>(row)], derivatives, values);
        rowSink(t, row, values);
      } catch (...) {
        errors[t] = std::current_exception();
        errorRow[t] = row;
      }
    }
  }
  std::size_t first = 0;
  for (std::size_t t = 1; t < errorRow.size(); ++t)
    if (errorRow[t] < errorRow[first]) first = t;
  if (errors[first]) std::rethrow_exception(errors[first]);
}

void checkSize(Index rows, Index columns) {
  constexpr auto limit = static_cast<Index>(std::numeric_limits<int>::max());
  if (rows > limit || columns > limit) {
    throw Error("shape-function matrix of " + std::to_string(rows) + " x " + std::to_string(columns) +
                " exceeds the 32-bit indices of SparseMatrix");
  }
}

}  // namespace

template <int D>
std::vector<Vec<D>> pointsOf(const Coordinates<D>& coordinates) {
  std::vector<Vec<D>> points(coordinates[0].size());
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int a = 0; a < D; ++a) points[i][a] = coordinates[static_cast<std::size_t>(a)][i];
  return points;
}

template <int D>
std::vector<SparseMatrix> shapeFunctionMatrices(const ShapeFunctions<D>& shapes, const std::vector<Vec<D>>& points,
                                                const std::vector<ShapeDerivative>& derivatives) {
  const int highest = checkedDerivatives<D>(derivatives);
  const auto rows = static_cast<Index>(points.size());
  const Index columns = shapes.nodeCount();
  checkSize(rows, columns);
  const int threads = threadCount();
  // triplets[thread][matrix]: no locking; each (row, column) occurs once, so the order in which
  // the threads' lists are concatenated does not change the matrix.
  std::vector<std::vector<std::vector<Triplet>>> triplets(static_cast<std::size_t>(threads),
                                                          std::vector<std::vector<Triplet>>(derivatives.size()));
  forEachRow<D>(shapes, points, highest, threads, [&](std::size_t t, Index row, const ShapeFunctionValues<D>& values) {
    for (std::size_t m = 0; m < derivatives.size(); ++m) {
      std::vector<Triplet>& list = triplets[t][m];
      for (std::size_t k = 0; k < values.nodes.size(); ++k) {
        list.emplace_back(static_cast<int>(row), static_cast<int>(values.nodes[k]),
                          entry<D>(values, k, derivatives[m]));
      }
    }
  });
  std::vector<SparseMatrix> matrices;
  matrices.reserve(derivatives.size());
  for (std::size_t m = 0; m < derivatives.size(); ++m) {
    std::vector<Triplet> all;
    std::size_t total = 0;
    for (const auto& perThread : triplets) total += perThread[m].size();
    all.reserve(total);
    for (auto& perThread : triplets) {
      all.insert(all.end(), perThread[m].begin(), perThread[m].end());
      std::vector<Triplet>().swap(perThread[m]);
    }
    SparseMatrix matrix(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(columns));
    matrix.setFromTriplets(all.begin(), all.end());
    matrices.push_back(std::move(matrix));
  }
  return matrices;
}

template <int D>
SparseMatrix shapeFunctionMatrix(const ShapeFunctions<D>& shapes, const std::vector<Vec<D>>& points,
                                 const ShapeDerivative& derivative) {
  return std::move(shapeFunctionMatrices<D>(shapes, points, {derivative}).front());
}

template <int D>
Eigen::MatrixXd denseShapeFunctionMatrix(const ShapeFunctions<D>& shapes, const std::vector<Vec<D>>& points,
                                         const ShapeDerivative& derivative) {
  const int highest = checkedDerivatives<D>({derivative});
  Eigen::MatrixXd matrix =
      Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(points.size()), static_cast<Eigen::Index>(shapes.nodeCount()));
  // Each row is written by one thread only.
  forEachRow<D>(shapes, points, highest, threadCount(),
                [&](std::size_t, Index row, const ShapeFunctionValues<D>& values) {
                  for (std::size_t k = 0; k < values.nodes.size(); ++k) {
                    matrix(static_cast<Eigen::Index>(row), static_cast<Eigen::Index>(values.nodes[k])) =
                        entry<D>(values, k, derivative);
                  }
                });
  return matrix;
}

#define MFWAVE_INSTANTIATE(D)                                                                                       \
  template std::vector<Vec<D>> pointsOf<D>(const Coordinates<D>&);                                                  \
  template std::vector<SparseMatrix> shapeFunctionMatrices<D>(const ShapeFunctions<D>&, const std::vector<Vec<D>>&, \
                                                              const std::vector<ShapeDerivative>&);                 \
  template SparseMatrix shapeFunctionMatrix<D>(const ShapeFunctions<D>&, const std::vector<Vec<D>>&,                \
                                               const ShapeDerivative&);                                             \
  template Eigen::MatrixXd denseShapeFunctionMatrix<D>(const ShapeFunctions<D>&, const std::vector<Vec<D>>&,        \
                                                       const ShapeDerivative&);
MFWAVE_INSTANTIATE(1)
MFWAVE_INSTANTIATE(2)
MFWAVE_INSTANTIATE(3)
#undef MFWAVE_INSTANTIATE

}  // namespace mfwave
