// Plots: gnuplot takes scripts of any size on its stdin, and output that is not a whole PNG
// is refused, naming the plot, instead of being written as one.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include "experiments/io/gnuplot.hpp"
#include "experiments/io/atomic_file.hpp"

namespace rice::experiments {
namespace {

namespace fs = std::filesystem;

const char* kTinyPlot = "set terminal pngcairo size 64,48\nset output 'plot.png'\nplot x\n";

class Gnuplot : public testing::Test {
 protected:
  void SetUp() override {
    fs::remove_all(folder_);
    make_output_folder(folder_);
    // Where gnuplot is missing, render_plot warns and returns false: nothing to test.
    if (!render_plot(folder_, "plot", kTinyPlot)) GTEST_SKIP() << "gnuplot (with pngcairo) is not installed";
  }
  void TearDown() override { fs::remove_all(folder_); }

  const fs::path folder_ = fs::temp_directory_path() / ("rice-gnuplot-" + std::to_string(::getpid()));
};

TEST_F(Gnuplot, ScriptsLargerThanAPipeBufferArePlotted) {
  std::string script = kTinyPlot;
  for (int line = 0; line < 4000; ++line) script += "# a comment line to make the script long: " + std::to_string(line) + "\n";
  ASSERT_GT(script.size(), 128u * 1024u);
  EXPECT_TRUE(render_plot(folder_, "plot", script));
  std::ifstream png(folder_ / "plot.png", std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(png), std::istreambuf_iterator<char>()};
  EXPECT_TRUE(bytes.starts_with("\x89PNG")) << "not a PNG";
}

TEST_F(Gnuplot, OutputThatIsNotAWholePngIsRefusedNamingThePlot) {
  fs::remove(folder_ / "text.png");
  try {
    render_plot(folder_, "text", "set terminal dumb\nset output 'text.png'\nplot x\n");
    ADD_FAILURE() << "text output was taken for a PNG";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("text.png"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(folder_ / "text.png"));
}

}  // namespace
}  // namespace rice::experiments
