#include "io/run/MemoryGuard.hpp"

#include "io/run/RunSummary.hpp"

#include <cmath>
#include <sstream>

namespace mfwave {

std::string memoryRefusal(const std::string& what, const MemoryEstimate& estimate, double machineMiB) {
  const double need = estimate.mib();
  if (!(need > machineMiB)) return {};
  std::ostringstream text;
  text.precision(3);
  text << what << " needs about " << need / 1024.0 << " GiB (" << static_cast<long long>(estimate.particles)
       << " particles at about " << static_cast<long long>(estimate.bytesPerParticle) << " bytes each: " << estimate.basis
       << "); this machine has " << machineMiB / 1024.0 << " GiB";
  return text.str();
}

std::string memoryRefusal(const std::string& what, const MemoryEstimate& estimate) {
  return memoryRefusal(what, estimate, physicalMemoryMiB());
}

}  // namespace mfwave
