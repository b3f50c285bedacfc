// A long parallel loop over independent items (grains, solver runs) with progress on a
// terminal and a clean stop on Ctrl-C: the one way the drivers loop over work in parallel.
#pragma once

#include <tbb/parallel_for.h>

#include <atomic>
#include <exception>
#include <mutex>
#include <string>

#include "experiments/io/interrupt.hpp"
#include "experiments/io/progress.hpp"

namespace rice::experiments {

/// Runs body(i) for i in [0, n) on TBB's workers, like tbb::parallel_for, reporting progress
/// as "label k/n". Unlike tbb::parallel_for it never cancels work in flight: after an
/// exception or a stop request no new item starts, the items already running finish, and
/// then the first exception (or Interrupted) is thrown here. An exception escaping a TBB task
/// would instead cancel the TBB algorithms nested in the other running items (OpenVDB's, the
/// solvers'), which then return incomplete results: interrupting `rice grains` that way
/// crashed it with SIGSEGV.
template <class Body>
void for_each_item(const std::string& label, int n, const Body& body) {
  Progress progress(label, n);
  std::atomic<int> done = 0;
  std::exception_ptr first_error;
  std::mutex error_mutex;
  std::atomic<bool> failed = false;
  tbb::parallel_for(0, n, [&](int i) {
    if (failed || stop_requested()) return;
    try {
      body(i);
      progress.update(++done);
    } catch (...) {
      const std::lock_guard lock(error_mutex);
      if (!first_error) first_error = std::current_exception();
      failed = true;
    }
  });
  if (first_error) std::rethrow_exception(first_error);
  stop_point();
  progress.finish();
}

}  // namespace rice::experiments
