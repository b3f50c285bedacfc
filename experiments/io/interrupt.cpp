// Signal flag and stop points (see interrupt.hpp).
#include "experiments/io/interrupt.hpp"

#include <atomic>
#include <csignal>
#include <mutex>

namespace rice::experiments {
namespace {

// Written by the handler, read by every worker thread: a lock-free atomic is safe for both.
std::atomic<int> g_signal = 0;
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void on_signal(int signal) { g_signal.store(signal, std::memory_order_relaxed); }

std::mutex g_activity_mutex;
std::string g_activity;

}  // namespace

Interrupted::Interrupted(int signal)
    : std::runtime_error(std::string("interrupted by ") + (signal == SIGINT ? "SIGINT" : "SIGTERM")),
      signal_(signal) {}

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  // Restart interrupted system calls (the run stops at its next stop point, not inside a
  // write), and restore the default so that a second signal ends the process at once.
  action.sa_flags = SA_RESTART | SA_RESETHAND;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

bool stop_requested() { return g_signal.load(std::memory_order_relaxed) != 0; }

void stop_point() {
  if (const int signal = g_signal.load(std::memory_order_relaxed)) throw Interrupted(signal);
}

void set_activity(std::string activity) {
  const std::lock_guard lock(g_activity_mutex);
  g_activity = std::move(activity);
}

std::string activity() {
  const std::lock_guard lock(g_activity_mutex);
  return g_activity;
}

}  // namespace rice::experiments
