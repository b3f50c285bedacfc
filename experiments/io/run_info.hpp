// run_info.txt: key–value lines describing a run (its settings, figures and timings), with the
// versions of the libraries and the compiler it was built with.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace rice::experiments {

/// Key–value lines describing a run: settings, thread count, timings, library versions.
std::string run_info(const std::vector<std::pair<std::string, std::string>>& entries);

}  // namespace rice::experiments
