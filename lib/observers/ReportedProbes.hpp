#pragma once
// Probe series with two values per sample: the raw value of the method's state at the probe and
// the value the method reports there (the same for most methods; the very weak SPH's published
// variant reports the deconvolved value of its eq. (35), collocation the field u^h = sum psi_J d_J
// it interpolates). The storage and the CSV are the same for every method, so a study that runs
// several methods on one problem (lamb2d) scores and writes their probes alike; a method's
// recorder derives from this class and says in observe() how it samples.

#include "observers/Observer.hpp"
#include "observers/ProbeRecorder.hpp"

#include <string>
#include <vector>

namespace mfwave {

class ReportedProbes : public Observer {
 public:
  explicit ReportedProbes(std::vector<Probe> probes);

  // The final state too (beginSample() skips it when the last observation was the same step),
  // unless switched off: a recorder standing in for a ProbeRecorder, which samples only on its
  // interval, keeps its rows.
  void end(const StateView& s) override {
    if (sampleAtEnd_) observe(s);
  }
  void sampleAtEnd(bool on) { sampleAtEnd_ = on; }

  const std::vector<Probe>& probes() const { return probes_; }
  const std::vector<Real>& times() const { return times_; }
  const std::vector<Real>& raw(std::size_t i) const { return raw_[i]; }
  const std::vector<Real>& reported(std::size_t i) const { return reported_[i]; }

  // Writes (atomically) "t [s]", then per probe <name>_raw, <name>_reported and, where exact[i]
  // is not empty (one value per sample), <name>_exact. `exact` has one entry per probe.
  void writeCsv(const std::string& path, const std::vector<std::vector<Real>>& exact) const;
  // The samples so far (a recorder deriving from this class keeps nothing else between steps).
  void saveState(StateArchive& archive) const override;
  void restoreState(const StateArchive& archive) override;

 protected:
  // Starts a sample at `time` and returns true, or returns false when the last sample was already
  // taken at that time or later (once per time).
  bool beginSample(Real time);
  // Probe i's values of the sample begun last.
  void add(std::size_t i, Real raw, Real reported);

 private:
  std::vector<Probe> probes_;
  std::vector<Real> times_;
  std::vector<std::vector<Real>> raw_, reported_;
  bool sampleAtEnd_ = true;
};

// The state's own value at each probe (component p.component of the probe's node or particle, D
// per node, of u or v) divided by `scale`; raw and reported are the same. The spectral elements'
// nodal values (scale 1), the UL-SPH at small amplitude eps (u = x - X and v over eps: the linear
// problem's unit-load response).
class NodalProbes : public ReportedProbes {
 public:
  NodalProbes(std::vector<Probe> probes, int dimension, Real scale = 1);
  void observe(const StateView& s) override;

 private:
  int dimension_;
  Real scale_;
};

}  // namespace mfwave
