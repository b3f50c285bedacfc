// Output helpers shared by the drivers; see output.hpp.
#include "experiments/output.hpp"

#include <Eigen/Core>
#include <oneapi/tbb/version.h>
#include <unistd.h>

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace rice::experiments {

void make_output_folder(const std::filesystem::path& folder) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) throw std::runtime_error("cannot create output folder " + folder.string() + ": " + error.message());
}

void write_text_atomically(const std::filesystem::path& path, const std::string& text) {
  const std::filesystem::path temporary = path.string() + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) throw std::runtime_error("cannot rename " + temporary.string() + " to " + path.string());
}

CsvTable::CsvTable(std::vector<std::string> header) : header_(std::move(header)) {}

void CsvTable::add_row(const std::vector<std::string>& cells) {
  if (cells.size() != header_.size())
    throw std::logic_error("CsvTable: row has " + std::to_string(cells.size()) + " cells, header " +
                           std::to_string(header_.size()));
  rows_.push_back(cells);
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

bool render_plot(const std::filesystem::path& folder, const std::string& name,
                 const std::string& gnuplot_script) {
  const std::filesystem::path script = folder / (name + ".gp");
  write_text_atomically(script, gnuplot_script);
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) {
    std::cerr << "note: gnuplot is not installed; run 'gnuplot " << script.string()
              << "' later to make the plot\n";
    return false;
  }
  const std::string command =
      "cd '" + folder.string() + "' && gnuplot '" + name + ".gp' 2>'" + name + ".gnuplot.log'";
  if (std::system(command.c_str()) != 0) {
    std::cerr << "warning: gnuplot failed on " << script.string() << " (see " << name
              << ".gnuplot.log)\n";
    return false;
  }
  std::filesystem::remove(folder / (name + ".gnuplot.log"));
  return true;
}

Progress::Progress(std::string label, int total)
    : label_(std::move(label)), total_(total), enabled_(isatty(fileno(stderr)) != 0),
      start_(std::chrono::steady_clock::now()) {}

void Progress::update(int done) {
  if (!enabled_ || done <= 0) return;
  const std::lock_guard lock(mutex_);
  const double elapsed = seconds_since(start_);
  const double left = elapsed / done * (total_ - done);
  std::fprintf(stderr, "\r%s %d/%d, %.0f s left   ", label_.c_str(), done, total_, left);
}

void Progress::finish() {
  if (enabled_) std::fprintf(stderr, "\r%s done in %.1f s          \n", label_.c_str(), seconds_since(start_));
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string run_info(const std::vector<std::pair<std::string, std::string>>& entries) {
  std::ostringstream out;
  for (const auto& [key, value] : entries) out << key << ": " << value << '\n';
  out << "eigen: " << EIGEN_WORLD_VERSION << '.' << EIGEN_MAJOR_VERSION << '.' << EIGEN_MINOR_VERSION << '\n';
  out << "tbb: " << TBB_VERSION_MAJOR << '.' << TBB_VERSION_MINOR << '\n';
  out << "compiler: " << __VERSION__ << '\n';
  return out.str();
}

}  // namespace rice::experiments
