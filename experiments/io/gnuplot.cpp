// gnuplot runner (see gnuplot.hpp).
#include "experiments/io/gnuplot.hpp"

#include <iostream>
#include <stdexcept>
#include <string_view>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/child_process.hpp"
#include "experiments/io/interrupt.hpp"

namespace rice::experiments {
namespace {

// A whole PNG: the signature, and the IEND chunk (length 0, type, CRC) that closes every PNG.
bool is_complete_png(std::string_view bytes) {
  constexpr std::string_view signature = "\x89PNG\r\n\x1a\n";
  constexpr std::string_view iend("\0\0\0\0IEND\xae\x42\x60\x82", 12);
  return bytes.starts_with(signature) && bytes.ends_with(iend);
}

}  // namespace

bool render_plot(const std::filesystem::path& folder, const std::string& name, const std::string& gnuplot_script) {
  const std::string output_line = "set output '" + name + ".png'";
  const size_t at = gnuplot_script.find(output_line);
  if (at == std::string::npos) throw std::logic_error("render_plot: the script for " + name + " lacks " + output_line);
  set_activity("plot " + name);  // named if a Ctrl-C arrives meanwhile
  const std::filesystem::path script = folder / (name + ".gp");
  write_file_atomically(script, gnuplot_script);

  std::string to_stdout = gnuplot_script;
  to_stdout.replace(at, output_line.size(), "set output");  // no file name: stdout
  ProgramRun gnuplot = run_program(folder, {"gnuplot"}, to_stdout);
  std::string& png = gnuplot.out;
  std::string& errors = gnuplot.err;
  if (!gnuplot.succeeded || png.empty()) {
    if (errors.empty()) errors = "gnuplot is not installed or could not start";
    std::cerr << "warning: no " << name << ".png (" << errors << "); run 'gnuplot " << name << ".gp' in "
              << folder.string() << " later\n";
    return false;
  }
  if (!is_complete_png(png))
    throw std::runtime_error("gnuplot's output for " + (folder / (name + ".png")).string() + " is not a complete PNG (" +
                             std::to_string(png.size()) + " bytes)");
  write_file_atomically(folder / (name + ".png"), png);
  return true;
}

std::string csv_plot_header(const std::string& name, int width, int height) {
  return "set terminal pngcairo size " + std::to_string(width) + "," + std::to_string(height) + "\nset output '" + name +
         ".png'\nset datafile separator ','\nset datafile missing 'nan'\n";
}

}  // namespace rice::experiments
