// run_info.txt; see run_info.hpp.
#include "experiments/io/run_info.hpp"

#include <Eigen/Core>
#include <oneapi/tbb/version.h>

#include <sstream>

namespace rice::experiments {

std::string run_info(const std::vector<std::pair<std::string, std::string>>& entries) {
  std::ostringstream out;
  for (const auto& [key, value] : entries) out << key << ": " << value << '\n';
  out << "eigen: " << EIGEN_WORLD_VERSION << '.' << EIGEN_MAJOR_VERSION << '.' << EIGEN_MINOR_VERSION << '\n';
  out << "tbb: " << TBB_VERSION_MAJOR << '.' << TBB_VERSION_MINOR << '\n';
  out << "compiler: " << __VERSION__ << '\n';
  return out.str();
}

}  // namespace rice::experiments
