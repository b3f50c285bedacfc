// Output helpers shared by the drivers; see output.hpp.
#include "experiments/output.hpp"

#include <Eigen/Core>
#include <fcntl.h>
#include <oneapi/tbb/version.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "experiments/interrupt.hpp"

namespace rice::experiments {

void make_output_folder(const std::filesystem::path& folder) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) throw std::runtime_error("cannot create output folder " + folder.string() + ": " + error.message());
}

namespace {

[[noreturn]] void fail_write(const std::filesystem::path& path, const std::string& what) {
  throw std::runtime_error("cannot write " + path.string() + ": " + what + ": " + std::strerror(errno));
}

void write_all(int fd, std::string_view bytes, const std::filesystem::path& path) {
  while (!bytes.empty()) {
    const ssize_t written = ::write(fd, bytes.data(), bytes.size());
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) fail_write(path, "write");
    bytes.remove_prefix(static_cast<size_t>(written));
  }
}

}  // namespace

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
  static std::atomic<unsigned> counter = 0;
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string.
  std::string hidden = ".";
  for (const std::string& piece : {path.filename().string(), std::string(".partial-"), std::to_string(::getpid()),
                                   std::string("-"), std::to_string(counter++)})
    hidden += piece;
  const std::filesystem::path temporary = folder / hidden;
  int fd = ::open(folder.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0644);
  const bool unnamed = fd >= 0;
  if (!unnamed) fd = ::open(temporary.c_str(), O_CREAT | O_TRUNC | O_WRONLY | O_CLOEXEC, 0644);
  if (fd < 0) fail_write(path, "open");
  try {
    write_all(fd, bytes, path);
    // The unnamed file gets its temporary name only now, complete.
    const std::string self = "/proc/self/fd/" + std::to_string(fd);
    if (unnamed) ::unlink(temporary.c_str());  // a stale name of a killed process with our pid
    if (unnamed && ::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, temporary.c_str(), AT_SYMLINK_FOLLOW) != 0)
      fail_write(path, "link");
    if (::close(std::exchange(fd, -1)) != 0) fail_write(path, "close");
    if (std::rename(temporary.c_str(), path.c_str()) != 0) fail_write(path, "rename");
  } catch (...) {
    if (fd >= 0) ::close(fd);
    ::unlink(temporary.c_str());
    throw;
  }
}

void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write) {
  std::ostringstream out;
  write(out);
  write_file_atomically(path, out.view());
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

Progress::Progress(std::string label, int total)
    : label_(std::move(label)), total_(total), enabled_(isatty(fileno(stderr)) != 0),
      start_(std::chrono::steady_clock::now()) {
  set_activity(label_ + " 0/" + std::to_string(total_) + " done");
}

void Progress::update(int done) {
  const std::lock_guard lock(mutex_);
  done_ = std::max(done_, done);
  set_activity(label_ + " " + std::to_string(done_) + "/" + std::to_string(total_) + " done");
  if (enabled_ && done > 0) {
    const double left = seconds_since(start_) / done * (total_ - done);
    std::fprintf(stderr, "\r%s %d/%d, %.0f s left   ", label_.c_str(), done, total_, left);
  }
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
