// Stopping a long run cleanly on Ctrl-C (SIGINT) or SIGTERM. The signal handler only sets a
// flag; long loops call stop_point(), which throws Interrupted, so the run unwinds through
// the ordinary error path: files already written stay complete (write_file_atomically) and
// the command exits non-zero, saying where it stopped. A second signal of the same kind
// ends the process at once. Parallel loops over items (grains, runs) go through
// for_each_item (item_loop.hpp), which stops between items without cancelling work in flight.
#pragma once

#include <stdexcept>
#include <string>

namespace rice::experiments {

/// Thrown by stop_point() once SIGINT or SIGTERM has arrived.
class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(int signal);
  int signal() const { return signal_; }

 private:
  int signal_;
};

/// Installs the handlers for SIGINT and SIGTERM (once per process; the `rice` command does).
void install_interrupt_handlers();

/// True once SIGINT or SIGTERM has arrived. Cheap: one atomic load.
bool stop_requested();

/// Throws Interrupted if a signal has arrived.
void stop_point();

/// What the run is doing, for the message on interruption ("grains 37/200 done");
/// Progress keeps it current. Thread-safe.
void set_activity(std::string activity);
std::string activity();

}  // namespace rice::experiments
