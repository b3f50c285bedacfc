// run_info.txt; see run_info.hpp.
#include "experiments/io/run_info.hpp"

#include <Eigen/Core>
#include <oneapi/tbb/version.h>

#include <fstream>
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

std::string run_info_value(const std::filesystem::path& file, const std::string& key) {
  std::ifstream info(file);
  const std::string prefix = key + ": ";
  for (std::string line; std::getline(info, line);)
    if (line.starts_with(prefix)) return line.substr(prefix.size());
  return "";
}

}  // namespace rice::experiments
