#pragma once
// A case that would need more memory than the machine has is refused before anything is
// allocated (issue 20), with the estimate: its particle count times what a particle of its method
// was measured to cost at the largest runs of the tradeoff sweep (peak memory over particles, the
// process's own ~15 MiB left out), with a margin. docs/reliability.md lists the figures.

#include <string>

namespace mfwave {

struct MemoryEstimate {
  double particles = 0;
  double bytesPerParticle = 0;
  std::string basis;  // what the figure is, e.g. "the UL-SPH in 2-D, 1.4 KiB measured"
  double mib() const { return particles * bytesPerParticle / (1024.0 * 1024.0); }
};

// Empty when `estimate` fits in `machineMiB`; else why not, for a message naming the key:
// "<what> needs about N GiB (P particles at about B bytes each: <basis>); this machine has M GiB".
std::string memoryRefusal(const std::string& what, const MemoryEstimate& estimate, double machineMiB);
// The same against this machine's physical memory (RunSummary's physicalMemoryMiB).
std::string memoryRefusal(const std::string& what, const MemoryEstimate& estimate);

}  // namespace mfwave
