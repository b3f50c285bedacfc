// Plots: a gnuplot script saved next to the CSV it plots, and its PNG, made by running
// gnuplot with the PNG on a pipe and writing it atomically like every other output (so a
// killed run never leaves half a PNG). gnuplot runs in a process group of its own, so the
// terminal's Ctrl-C reaches only rice, which stops once the plot is written.
#pragma once

#include <filesystem>
#include <string>

namespace rice::experiments {

/// Writes `<folder>/<name>.gp` (which must contain `set output '<name>.png'`, so that it can
/// be rerun by hand) and makes `<folder>/<name>.png` with gnuplot, run in `folder`. Returns
/// false, with a message on stderr, when gnuplot is not installed or fails: the CSV and the
/// script stay, so the plot can be made later. Scripts may be of any size. Throws
/// std::logic_error if the script lacks its set output line, and std::runtime_error naming
/// the PNG if gnuplot's output is not a whole PNG (signature to IEND chunk).
bool render_plot(const std::filesystem::path& folder, const std::string& name, const std::string& gnuplot_script);

/// The lines a plot of CSV files starts with: `<name>.png` of width × height pixels, fields
/// separated by commas, `nan` for a missing value.
std::string csv_plot_header(const std::string& name, int width, int height);

/// Both axes logarithmic and labelled as powers of ten.
inline constexpr const char* kLogLogAxes = "set logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\n";

}  // namespace rice::experiments
