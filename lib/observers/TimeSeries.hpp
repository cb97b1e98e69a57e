#pragma once
// A table of samples in time: one row per observation, named columns (with units in the names).
// Observers fill it; writeCsv() writes it atomically (temporary file, then rename).

#include "core/StateArchive.hpp"
#include "core/Types.hpp"

#include <string>
#include <vector>

namespace mfwave {

class TimeSeries {
 public:
  // The first column is always the time; `columns` names the others, e.g. "u_z at centre [m]".
  TimeSeries(std::string timeColumn, std::vector<std::string> columns);

  void append(Real time, const std::vector<Real>& values);

  std::size_t rows() const { return times_.size(); }
  std::size_t columns() const { return names_.size(); }
  const std::vector<Real>& times() const { return times_; }
  // Column c of every row (c indexes the named columns, time excluded).
  std::vector<Real> column(std::size_t c) const;
  const std::vector<std::string>& names() const { return names_; }

  void writeCsv(const std::string& path) const;

  // The rows (for checkpoints); restoreState checks the column count.
  void saveState(StateArchive& archive) const;
  void restoreState(const StateArchive& archive);

 private:
  std::string timeName_;
  std::vector<std::string> names_;
  std::vector<Real> times_;
  std::vector<Real> values_;  // row-major, rows() x columns()
};

}  // namespace mfwave
