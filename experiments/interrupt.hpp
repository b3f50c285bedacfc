// Stopping a long run cleanly on Ctrl-C (SIGINT) or SIGTERM. The signal handler only sets a
// flag; long loops call stop_point(), which throws Interrupted, so the run unwinds through
// the ordinary error path: files already written stay complete (write_file_atomically) and
// the command exits non-zero, saying where it stopped. A second signal of the same kind
// ends the process at once. Parallel loops over items (grains, runs) go through
// for_each_item, which stops between items without cancelling the work in flight.
#pragma once

#include <tbb/parallel_for.h>

#include <atomic>
#include <exception>
#include <mutex>
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

/// Runs body(i) for i in [0, n) on TBB's workers, like tbb::parallel_for, except that it never
/// cancels work in flight: after an exception or a stop request no new item starts, the
/// items already running finish, and then the first exception (or Interrupted) is thrown
/// here. An exception escaping a TBB task would instead cancel the TBB algorithms nested in
/// the other running items (OpenVDB's, the solvers'), which then return incomplete results:
/// interrupting `rice grains` that way crashed it with SIGSEGV.
template <class Body>
void for_each_item(int n, const Body& body) {
  std::exception_ptr first_error;
  std::mutex error_mutex;
  std::atomic<bool> failed = false;
  tbb::parallel_for(0, n, [&](int i) {
    if (failed || stop_requested()) return;
    try {
      body(i);
    } catch (...) {
      const std::lock_guard lock(error_mutex);
      if (!first_error) first_error = std::current_exception();
      failed = true;
    }
  });
  if (first_error) std::rethrow_exception(first_error);
  stop_point();
}

}  // namespace rice::experiments
