// Running a helper program as a child; see child_process.hpp.
#include "experiments/io/child_process.hpp"

#include <fcntl.h>
#include <limits.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <utility>

#include "experiments/io/file_descriptor.hpp"

extern char** environ;

namespace rice::experiments {
namespace {

// A pipe whose ends are closed in this process at exec (O_CLOEXEC), so that no other child
// started meanwhile inherits them and holds the child's stdin open.
struct Pipe {
  FileDescriptor read, write;
  bool open() {
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) return false;
    read.reset(fds[0]);
    write.reset(fds[1]);
    return true;
  }
};

// The child, reaped on every path: if it still runs when the scope is left early (an
// exception), it is killed first, so no run leaves a child or a zombie behind.
class Child {
 public:
  Child() = default;
  ~Child() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGKILL);
    wait_success();
  }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;

  void adopt(pid_t pid) { pid_ = pid; }

  // Waits for the child; true when it exited with status 0.
  bool wait_success() {
    int status = 0;
    pid_t reaped = 0;
    do reaped = ::waitpid(pid_, &status, 0);
    while (reaped < 0 && errno == EINTR);
    pid_ = 0;
    return reaped > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
  }

 private:
  pid_t pid_ = 0;
};

// SIGPIPE blocked in this thread while it writes to the child, so that a child that exits
// before reading its whole input turns into EPIPE here instead of ending the run. A SIGPIPE
// raised meanwhile is consumed before the old mask comes back.
class SigpipeBlocked {
 public:
  SigpipeBlocked() {
    sigemptyset(&pipe_);
    sigaddset(&pipe_, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &pipe_, &old_);
  }
  ~SigpipeBlocked() {
    const timespec now{};
    if (!sigismember(&old_, SIGPIPE))
      while (sigtimedwait(&pipe_, nullptr, &now) == SIGPIPE) {
      }
    pthread_sigmask(SIG_SETMASK, &old_, nullptr);
  }
  SigpipeBlocked(const SigpipeBlocked&) = delete;
  SigpipeBlocked& operator=(const SigpipeBlocked&) = delete;

 private:
  sigset_t pipe_{}, old_{};
};

// Starts argv in `folder` with the pipes as its stdin, stdout and stderr, in a process group
// of its own. False if it cannot start.
bool start(const std::filesystem::path& folder, const std::vector<std::string>& argv, Pipe& in, Pipe& out, Pipe& err,
           Child& child) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, folder.c_str());
  // dup2 clears O_CLOEXEC on the copies; the originals close at exec.
  posix_spawn_file_actions_adddup2(&actions, in.read.get(), STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, out.write.get(), STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, err.write.get(), STDERR_FILENO);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attributes, 0);
  std::vector<std::string> copies = argv;  // posix_spawnp takes char*
  std::vector<char*> pointers;
  for (std::string& a : copies) pointers.push_back(a.data());
  pointers.push_back(nullptr);
  pid_t pid = 0;
  const bool started = posix_spawnp(&pid, pointers[0], &actions, &attributes, pointers.data(), environ) == 0;
  posix_spawnattr_destroy(&attributes);
  posix_spawn_file_actions_destroy(&actions);
  if (started) child.adopt(pid);
  return started;
}

// Writes `script` to the child's stdin while reading its stdout and stderr, all in one poll
// loop: writing it all first would block on a script larger than the pipe's buffer while
// the child blocks on its full stdout. Ends when the child has closed both outputs.
void exchange(Pipe& in, Pipe& out, Pipe& err, std::string_view script, std::string& out_text,
              std::string& err_text) {
  const SigpipeBlocked sigpipe_blocked;
  std::array<pollfd, 3> fds{{{out.read.get(), POLLIN, 0}, {err.read.get(), POLLIN, 0}, {in.write.get(), POLLOUT, 0}}};
  std::array<std::string*, 2> sinks{&out_text, &err_text};
  const auto close_stdin = [&] {  // the script's end, or the child stopped reading
    in.write.reset();
    fds[2].fd = -1;  // poll skips negative descriptors
  };
  if (script.empty()) close_stdin();
  while (fds[0].fd >= 0 || fds[1].fd >= 0) {
    if (::poll(fds.data(), fds.size(), -1) < 0) {
      if (errno == EINTR) continue;  // a signal (Ctrl-C): the run stops after the plot
      return;
    }
    if (fds[2].fd >= 0 && fds[2].revents != 0) {
      // At most PIPE_BUF bytes: what POLLOUT promises can be written without blocking.
      const ssize_t n = ::write(fds[2].fd, script.data(), std::min<size_t>(script.size(), PIPE_BUF));
      if (n > 0) script.remove_prefix(static_cast<size_t>(n));
      if ((n < 0 && errno != EINTR && errno != EAGAIN) || script.empty()) close_stdin();
    }
    for (size_t k = 0; k < sinks.size(); ++k) {
      if (fds[k].fd < 0 || fds[k].revents == 0) continue;
      char buffer[65536];
      const ssize_t n = ::read(fds[k].fd, buffer, sizeof buffer);
      if (n > 0) {
        sinks[k]->append(buffer, static_cast<size_t>(n));
      } else if (n == 0 || errno != EINTR) {
        fds[k].fd = -1;  // end of file
      }
    }
  }
}

}  // namespace

ProgramRun run_program(const std::filesystem::path& folder, const std::vector<std::string>& argv,
                       std::string_view input) {
  ProgramRun run;
  Pipe in, stdout_pipe, stderr_pipe;
  if (argv.empty() || !in.open() || !stdout_pipe.open() || !stderr_pipe.open()) return run;
  Child child;
  if (!start(folder, argv, in, stdout_pipe, stderr_pipe, child)) return run;
  run.started = true;
  // The child's ends, closed here so that its exit ends our reads and writes.
  in.read.reset();
  stdout_pipe.write.reset();
  stderr_pipe.write.reset();
  exchange(in, stdout_pipe, stderr_pipe, input, run.out, run.err);
  run.succeeded = child.wait_success();
  return run;
}

}  // namespace rice::experiments
