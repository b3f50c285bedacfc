// CSV tables with a header row, written by every driver next to its plot so anyone can
// re-plot it; numbers in the shortest text that reads back to the same double.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace rice::experiments {

/// A CSV table built row by row; numbers are written with full precision.
class CsvTable {
 public:
  explicit CsvTable(std::vector<std::string> header);
  void add_row(const std::vector<std::string>& cells);
  std::string text() const;
  /// The rows so far, and replacing them (a run resumed from a checkpoint).
  const std::vector<std::vector<std::string>>& rows() const { return rows_; }
  void set_rows(std::vector<std::vector<std::string>> rows) { rows_ = std::move(rows); }
  /// The index of the column named `name`; std::out_of_range if there is none.
  size_t column(const std::string& name) const;

 private:
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

/// Number formatting for CSV cells: shortest text that reads back to the same double.
std::string cell(double value);
std::string cell(long value);
inline std::string cell(int value) { return cell(static_cast<long>(value)); }
/// `value` with `decimals` digits after the point, for titles and messages.
std::string fixed(double value, int decimals);

}  // namespace rice::experiments
