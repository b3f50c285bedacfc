// run_info.txt: key–value lines describing a run (its settings, figures and timings), with the
// versions of the libraries and the compiler it was built with.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace rice::experiments {

/// Key–value lines describing a run: settings, thread count, timings, library versions.
std::string run_info(const std::vector<std::pair<std::string, std::string>>& entries);

/// The value of `key` in the run_info.txt at `file`; "" when the file or the key is missing.
std::string run_info_value(const std::filesystem::path& file, const std::string& key);

}  // namespace rice::experiments
