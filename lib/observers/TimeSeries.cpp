#include "observers/TimeSeries.hpp"

#include "core/AtomicFile.hpp"
#include "core/Error.hpp"

namespace mfwave {

TimeSeries::TimeSeries(std::string timeColumn, std::vector<std::string> columns)
    : timeName_(std::move(timeColumn)), names_(std::move(columns)) {}

void TimeSeries::append(Real time, const std::vector<Real>& values) {
  if (values.size() != names_.size())
    throw Error("time series: a row has " + std::to_string(values.size()) + " values for " +
                std::to_string(names_.size()) + " columns");
  times_.push_back(time);
  values_.insert(values_.end(), values.begin(), values.end());
}

std::vector<Real> TimeSeries::column(std::size_t c) const {
  std::vector<Real> out(rows());
  for (std::size_t r = 0; r < rows(); ++r) out[r] = values_[r * columns() + c];
  return out;
}

void TimeSeries::writeCsv(const std::string& path) const {
  AtomicFile file(path);
  auto& out = file.stream();
  out << timeName_;
  for (const auto& name : names_) out << ',' << name;
  out << '\n';
  for (std::size_t r = 0; r < rows(); ++r) {
    out << times_[r];
    for (std::size_t c = 0; c < columns(); ++c) out << ',' << values_[r * columns() + c];
    out << '\n';
  }
  file.commit();
}

void TimeSeries::saveState(StateArchive& archive) const {
  archive.put("times", times_);
  archive.put("values", values_);
}

void TimeSeries::restoreState(const StateArchive& archive) {
  const std::vector<Real>& times = archive.get("times");
  const std::vector<Real>& values = archive.get("values");
  if (values.size() != times.size() * names_.size())
    throw InputError("--restart", "the checkpoint's time series has " + std::to_string(values.size()) +
                                      " values for " + std::to_string(times.size()) + " rows of " +
                                      std::to_string(names_.size()) + " columns");
  times_ = times;
  values_ = values;
}

}  // namespace mfwave
