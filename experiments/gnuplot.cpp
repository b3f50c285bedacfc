// gnuplot runner (see gnuplot.hpp).
#include "experiments/gnuplot.hpp"

#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <iostream>
#include <stdexcept>

#include "experiments/output.hpp"

extern char** environ;

namespace rice::experiments {
namespace {

// Runs gnuplot in `folder` on `script` (given on stdin); its stdout and stderr come back.
// The script is written into the pipe before gnuplot starts, so a gnuplot that dies early
// cannot raise SIGPIPE here; scripts are far smaller than a pipe's buffer.
bool run_gnuplot(const std::filesystem::path& folder, const std::string& script, std::string& out, std::string& err) {
  std::array<int, 2> in_pipe{}, out_pipe{}, err_pipe{};
  if (pipe(in_pipe.data()) != 0 || pipe(out_pipe.data()) != 0 || pipe(err_pipe.data()) != 0) return false;
  const bool written = script.size() < 16384 && write(in_pipe[1], script.data(), script.size()) ==
                                                    static_cast<ssize_t>(script.size());
  close(in_pipe[1]);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, folder.c_str());
  posix_spawn_file_actions_adddup2(&actions, in_pipe[0], STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, out_pipe[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, err_pipe[1], STDERR_FILENO);
  for (const int fd : {in_pipe[0], out_pipe[0], out_pipe[1], err_pipe[0], err_pipe[1]})
    posix_spawn_file_actions_addclose(&actions, fd);
  char name[] = "gnuplot";
  char* argv[] = {name, nullptr};
  pid_t pid = 0;
  const bool started = written && posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ) == 0;
  posix_spawn_file_actions_destroy(&actions);
  for (const int fd : {in_pipe[0], out_pipe[1], err_pipe[1]}) close(fd);

  std::array<pollfd, 2> fds{{{out_pipe[0], POLLIN, 0}, {err_pipe[0], POLLIN, 0}}};
  std::array<std::string*, 2> sinks{&out, &err};
  for (int open = started ? 2 : 0; open > 0;) {
    if (poll(fds.data(), fds.size(), -1) < 0) {
      if (errno == EINTR) continue;
      break;
    }
    for (size_t k = 0; k < fds.size(); ++k) {
      if (fds[k].fd < 0 || fds[k].revents == 0) continue;
      char buffer[65536];
      const ssize_t n = read(fds[k].fd, buffer, sizeof buffer);
      if (n > 0) {
        sinks[k]->append(buffer, static_cast<size_t>(n));
      } else if (n == 0 || errno != EINTR) {
        fds[k].fd = -1;  // end of file
        --open;
      }
    }
  }
  close(out_pipe[0]);
  close(err_pipe[0]);
  int status = 0;
  return started && waitpid(pid, &status, 0) == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace

bool render_plot(const std::filesystem::path& folder, const std::string& name, const std::string& gnuplot_script) {
  const std::string output_line = "set output '" + name + ".png'";
  const size_t at = gnuplot_script.find(output_line);
  if (at == std::string::npos) throw std::logic_error("render_plot: the script for " + name + " lacks " + output_line);
  const std::filesystem::path script = folder / (name + ".gp");
  write_file_atomically(script, gnuplot_script);

  std::string to_stdout = gnuplot_script;
  to_stdout.replace(at, output_line.size(), "set output");  // no file name: stdout
  std::string png, errors;
  if (!run_gnuplot(folder, to_stdout, png, errors) || png.empty()) {
    if (errors.empty()) errors = "gnuplot is not installed or could not start";
    std::cerr << "warning: no " << name << ".png (" << errors << "); run 'gnuplot " << name << ".gp' in "
              << folder.string() << " later\n";
    return false;
  }
  write_file_atomically(folder / (name + ".png"), png);
  return true;
}

}  // namespace rice::experiments
