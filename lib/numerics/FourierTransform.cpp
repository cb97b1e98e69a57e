#include "numerics/FourierTransform.hpp"

#include "core/Error.hpp"

#include <fftw3.h>

#include <mutex>
#include <string>

namespace mfwave {

namespace {
std::mutex& plannerMutex() {
  static std::mutex mutex;
  return mutex;
}
}  // namespace

void forwardFourierTransform(ComplexVector& data, int rank, int cells) {
  if (rank < 1 || rank > 3) throw InputError("rank", "must be 1, 2 or 3, got " + std::to_string(rank));
  std::size_t expected = 1;
  for (int d = 0; d < rank; ++d) expected *= static_cast<std::size_t>(cells);
  if (cells < 1 || data.size() != expected)
    throw InputError("cells", std::to_string(data.size()) + " values are not " + std::to_string(cells) + "^" +
                                  std::to_string(rank));
  const int n[3] = {cells, cells, cells};
  auto* buffer = reinterpret_cast<fftw_complex*>(data.data());
  fftw_plan plan = nullptr;
  {
    // FFTW_ESTIMATE plans without touching the data, so the input survives planning.
    std::lock_guard<std::mutex> lock(plannerMutex());
    plan = fftw_plan_dft(rank, n, buffer, buffer, FFTW_FORWARD, FFTW_ESTIMATE);
  }
  if (plan == nullptr) throw Error("forwardFourierTransform: FFTW could not plan a transform of " + std::to_string(cells));
  fftw_execute(plan);
  std::lock_guard<std::mutex> lock(plannerMutex());
  fftw_destroy_plan(plan);
}

}  // namespace mfwave
