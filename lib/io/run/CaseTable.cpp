#include "io/run/CaseTable.hpp"

#include "core/AtomicFile.hpp"

#include <iomanip>
#include <ostream>

namespace mfwave {

void TableCell::write(std::ostream& out) const {
  std::visit(
      [&out](const auto& v) {
        if constexpr (!std::is_same_v<std::decay_t<decltype(v)>, std::monostate>) out << v;
      },
      value_);
}

void TerminalColumn::writeTitle(std::ostream& out) const {
  const auto flags = out.flags();
  out << (alignLeft ? std::left : std::right) << std::setw(titleWidth > 0 ? titleWidth : width) << title;
  out.flags(flags);
}

void TerminalColumn::writeCell(std::ostream& out, const TableCell& cell) const {
  const auto flags = out.flags();
  const auto oldPrecision = out.precision();
  out << (alignLeft ? std::left : std::right) << std::setprecision(digits);
  if (notation == Notation::Scientific) out << std::scientific;
  if (notation == Notation::Fixed) out << std::fixed;
  out << std::setw(width);
  if (cell.empty())
    out << "";
  else
    cell.write(out);  // setw applies to the value's one insertion
  out << suffix;
  out.flags(flags);
  out.precision(oldPrecision);
}

void writeCsvLines(const std::string& path, const std::vector<std::vector<TableCell>>& lines,
                   const std::vector<std::string>& header, int precision) {
  AtomicFile file(path);
  std::ostream& out = file.stream();
  for (std::size_t i = 0; i < header.size(); ++i) out << (i ? "," : "") << header[i];
  out << '\n' << std::setprecision(precision);
  for (const auto& line : lines) {
    for (std::size_t i = 0; i < line.size(); ++i) {
      if (i) out << ',';
      line[i].write(out);
    }
    out << '\n';
  }
  file.commit();
}

}  // namespace mfwave
