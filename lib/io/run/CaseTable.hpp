#pragma once
// One description of a study's per-case table, written two ways: as a CSV file (every column, at
// one precision for the whole file) and as the terminal table (the columns a reader scans, each
// with its own width and format). A driver names each column once, with the function that reads
// it from a case, so the file and the terminal cannot disagree on what a column holds.
//
//   CaseTable<Case> table;
//   table.column("dx [m]", [](const Case& c) { return c.dx; }, TerminalColumn{"dx", 9}.precision(4));
//   table.writeCsv(folder + "/cases.csv", cases, 10);
//   table.print(std::cout, cases);

#include "core/Types.hpp"

#include <functional>
#include <ostream>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace mfwave {

// One cell: empty, a whole number, a real or text. Whole numbers stay whole (a particle count of
// 1,234,567 is written as such, not as 1.23457e+06); an empty cell is written as nothing, while a
// NaN real is written "nan" (a value that was computed and is not a number).
class TableCell {
 public:
  TableCell() = default;
  template <class T, std::enable_if_t<std::is_integral_v<T> && !std::is_same_v<T, bool>, int> = 0>
  TableCell(T value) : value_(static_cast<long long>(value)) {}
  template <class T, std::enable_if_t<std::is_floating_point_v<T>, int> = 0>
  TableCell(T value) : value_(static_cast<double>(value)) {}
  TableCell(std::string text) : value_(std::move(text)) {}
  TableCell(const char* text) : value_(std::string(text)) {}

  bool empty() const { return std::holds_alternative<std::monostate>(value_); }
  // Written into `out` with out's current format flags and precision.
  void write(std::ostream& out) const;

 private:
  std::variant<std::monostate, long long, double, std::string> value_;
};

// How a column looks on the terminal: its title, width and the format of its numbers.
struct TerminalColumn {
  enum class Notation { Default, Scientific, Fixed };
  std::string title;
  int width = 10;
  int digits = 4;                  // std::setprecision
  Notation notation = Notation::Default;
  bool alignLeft = false;
  int titleWidth = 0;              // 0: the column's width
  std::string suffix;              // written after the value, e.g. "%"

  TerminalColumn(std::string title_, int width_) : title(std::move(title_)), width(width_) {}
  TerminalColumn& precision(int d) { digits = d; return *this; }
  TerminalColumn& scientific() { notation = Notation::Scientific; return *this; }
  TerminalColumn& fixed() { notation = Notation::Fixed; return *this; }
  TerminalColumn& left() { alignLeft = true; return *this; }
  TerminalColumn& titledIn(int w) { titleWidth = w; return *this; }
  TerminalColumn& followedBy(std::string s) { suffix = std::move(s); return *this; }

  void writeTitle(std::ostream& out) const;
  void writeCell(std::ostream& out, const TableCell& cell) const;
};

// Writes `lines` (header first) to `path` atomically (a temporary name, then a rename).
void writeCsvLines(const std::string& path, const std::vector<std::vector<TableCell>>& lines,
                   const std::vector<std::string>& header, int precision);

template <class Case>
class CaseTable {
 public:
  using Value = std::function<TableCell(const Case&)>;

  // A column of the CSV file; with `terminal`, also a column of the terminal table.
  CaseTable& column(std::string header, Value value, std::optional<TerminalColumn> terminal = std::nullopt) {
    columns_.push_back({std::move(header), std::move(value), std::move(terminal)});
    return *this;
  }
  // A column on the terminal only.
  CaseTable& terminalOnly(TerminalColumn terminal, Value value) {
    columns_.push_back({std::string(), std::move(value), std::move(terminal)});
    return *this;
  }

  // The CSV file: a header line and a line per case, numbers with `precision` significant digits.
  void writeCsv(const std::string& path, const std::vector<Case>& cases, int precision) const {
    std::vector<std::string> header;
    for (const Column& c : columns_)
      if (!c.header.empty()) header.push_back(c.header);
    std::vector<std::vector<TableCell>> lines;
    for (const Case& item : cases) {
      std::vector<TableCell> line;
      for (const Column& c : columns_)
        if (!c.header.empty()) line.push_back(c.value(item));
      lines.push_back(std::move(line));
    }
    writeCsvLines(path, lines, header, precision);
  }

  // The terminal table: a title line and a line per case.
  void print(std::ostream& out, const std::vector<Case>& cases) const {
    for (const Column& c : columns_)
      if (c.terminal) c.terminal->writeTitle(out);
    out << '\n';
    for (const Case& item : cases) {
      for (const Column& c : columns_)
        if (c.terminal) c.terminal->writeCell(out, c.value(item));
      out << '\n';
    }
  }

 private:
  struct Column {
    std::string header;  // empty: terminal only
    Value value;
    std::optional<TerminalColumn> terminal;
  };
  std::vector<Column> columns_;
};

// An empty cell where a value is not defined (an observed order on the coarsest case, a probe
// without a reference), the value elsewhere.
inline TableCell cellIf(bool defined, Real value) { return defined ? TableCell(value) : TableCell(); }

}  // namespace mfwave
