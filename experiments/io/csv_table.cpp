// CSV tables; see csv_table.hpp.
#include "experiments/io/csv_table.hpp"

#include <algorithm>
#include <charconv>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace rice::experiments {

CsvTable::CsvTable(std::vector<std::string> header) : header_(std::move(header)) {}

void CsvTable::add_row(const std::vector<std::string>& cells) {
  if (cells.size() != header_.size())
    throw std::logic_error("CsvTable: row has " + std::to_string(cells.size()) + " cells, header " +
                           std::to_string(header_.size()));
  rows_.push_back(cells);
}

size_t CsvTable::column(const std::string& name) const {
  const auto it = std::find(header_.begin(), header_.end(), name);
  if (it == header_.end()) throw std::out_of_range("CsvTable: no column " + name);
  return static_cast<size_t>(it - header_.begin());
}

std::string CsvTable::text() const {
  std::ostringstream out;
  const auto line = [&](const std::vector<std::string>& cells) {
    for (size_t i = 0; i < cells.size(); ++i) out << (i ? "," : "") << cells[i];
    out << '\n';
  };
  line(header_);
  for (const auto& row : rows_) line(row);
  return out.str();
}

std::string cell(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string cell(long value) { return std::to_string(value); }

std::string fixed(double value, int decimals) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, decimals);
  return std::string(buffer, result.ptr);
}

}  // namespace rice::experiments
