// What every study and figure driver writes: an output folder, files written atomically (so
// a run that fails, is interrupted or is killed leaves complete files or none), CSV tables
// with a header row, a run-info file, and progress lines on a terminal (quiet when stderr is
// not a terminal, as in CI). Plots: gnuplot.hpp.
#pragma once

#include <chrono>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

namespace rice::experiments {

/// Creates `folder` (and parents); throws with the path on failure. Removes the hidden
/// temporaries `.<name>.partial-<pid>-<n>` that runs killed while using the fallback of
/// write_file_atomically left in it (those of processes still running stay).
void make_output_folder(const std::filesystem::path& folder);

/// Writes `bytes` to `path` so that `path` is, at every instant, absent, its old complete
/// content or the new complete content, even if the process is killed (SIGKILL included).
/// The bytes go to an unnamed file in the same folder (Linux O_TMPFILE); once complete, an
/// old `path` is unlinked and the unnamed file linked as `path` (linkat through /proc), so no
/// other name ever exists. Where that is impossible (no O_TMPFILE on the file system, /proc
/// not mounted), a hidden temporary `.<name>.partial-<pid>-<n>` is written and renamed onto
/// `path`; a kill can leave that temporary behind, never a partial `path`, and the next
/// make_output_folder on the folder removes it. Throws std::runtime_error naming the path.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

/// The same for a writer that streams its content (e.g. grains::write_ply).
void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write);

/// A CSV table built row by row; numbers are written with full precision.
class CsvTable {
 public:
  explicit CsvTable(std::vector<std::string> header);
  void add_row(const std::vector<std::string>& cells);
  std::string text() const;

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

/// Progress of a long loop: lines "label k/N, ETA" on stderr when stderr is a terminal, and
/// the activity reported if the run is interrupted (interrupt.hpp). Thread-safe.
class Progress {
 public:
  Progress(std::string label, int total);
  void update(int done);
  void finish();

 private:
  std::string label_;
  int total_;
  int done_ = 0;
  bool enabled_;
  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
};

/// Seconds since `start` on the steady clock.
double seconds_since(std::chrono::steady_clock::time_point start);

/// Key–value lines describing a run: settings, thread count, timings, library versions.
std::string run_info(const std::vector<std::pair<std::string, std::string>>& entries);

}  // namespace rice::experiments
