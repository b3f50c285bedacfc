// Numeric CSV reader (numeric_csv.hpp).
#include "experiments/io/numeric_csv.hpp"

#include <charconv>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace rice::experiments {
namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

}  // namespace

int NumericCsv::column(const std::string& name) const {
  for (size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return static_cast<int>(i);
  throw std::runtime_error(path.string() + ": no column '" + name + "'");
}

NumericCsv read_numeric_csv(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot be read");
  NumericCsv csv;
  csv.path = path;
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(path.string() + ": empty, expected a header row");
  csv.columns = split(line);
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    const std::vector<std::string> cells = split(line);
    if (cells.size() != csv.columns.size())
      throw std::runtime_error(path.string() + ":" + std::to_string(number) + ": " + std::to_string(cells.size()) +
                               " cells, the header has " + std::to_string(csv.columns.size()));
    std::vector<double> row;
    for (const std::string& cell : cells) {
      double value = 0.0;
      const auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
      if (error != std::errc() || end != cell.data() + cell.size())
        throw std::runtime_error(path.string() + ":" + std::to_string(number) + ": '" + cell + "' is not a number");
      row.push_back(value);
    }
    csv.rows.push_back(std::move(row));
  }
  return csv;
}

}  // namespace rice::experiments
