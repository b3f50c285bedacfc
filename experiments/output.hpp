// What every study and figure driver writes: an output folder, files written atomically (a
// temporary name, then rename, so a failed run leaves nothing half-written), CSV tables with
// a header row, gnuplot scripts rendered to PNG next to their CSV, a run-info file, and
// progress lines on a terminal (quiet when stderr is not a terminal, as in CI).
#pragma once

#include <chrono>
#include <mutex>
#include <filesystem>
#include <string>
#include <vector>

namespace rice::experiments {

/// Creates `folder` (and parents); throws with the path on failure.
void make_output_folder(const std::filesystem::path& folder);

/// Writes `text` to `path` via a temporary file in the same folder and a rename.
void write_text_atomically(const std::filesystem::path& path, const std::string& text);

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

/// Writes `<folder>/<name>.gp` and runs gnuplot on it to make `<folder>/<name>.png`.
/// Returns false (with a message on stderr) when gnuplot is not installed or fails; the CSV
/// and the script stay, so the plot can be made later.
bool render_plot(const std::filesystem::path& folder, const std::string& name,
                 const std::string& gnuplot_script);

/// Progress lines "label k/N, ETA" on stderr, only when stderr is a terminal. Thread-safe.
class Progress {
 public:
  Progress(std::string label, int total);
  void update(int done);
  void finish();

 private:
  std::string label_;
  int total_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
};

/// Seconds since `start` on the steady clock.
double seconds_since(std::chrono::steady_clock::time_point start);

/// Key–value lines describing a run: settings, thread count, timings, library versions.
std::string run_info(const std::vector<std::pair<std::string, std::string>>& entries);

}  // namespace rice::experiments
