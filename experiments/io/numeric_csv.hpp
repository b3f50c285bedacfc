// Reading back the CSV tables the drivers write (a header row, then rows of numbers), for
// commands that build on another command's output (`rice render --run`).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rice::experiments {

struct NumericCsv {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;

  /// Index of column `name`; throws std::runtime_error naming the file when it is missing.
  int column(const std::string& name) const;
  std::filesystem::path path;
};

/// Throws std::runtime_error naming the file and line of anything that is not a number, or a
/// row whose length differs from the header's.
NumericCsv read_numeric_csv(const std::filesystem::path& path);

}  // namespace rice::experiments
