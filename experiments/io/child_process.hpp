// Running a helper program (gnuplot, ffmpeg) as a child: in a folder, in a process group of
// its own (so that the terminal's Ctrl-C reaches only rice, which stops once the child is
// done), with a text on its stdin and its stdout and stderr read back; always reaped.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace rice::experiments {

struct ProgramRun {
  bool started = false;    ///< false: not installed, or it could not start
  bool succeeded = false;  ///< it exited with status 0
  std::string out, err;
};

/// Runs `argv` (argv[0] looked up on the PATH) in `folder` with `input` on its stdin.
ProgramRun run_program(const std::filesystem::path& folder, const std::vector<std::string>& argv,
                       std::string_view input = {});

}  // namespace rice::experiments
