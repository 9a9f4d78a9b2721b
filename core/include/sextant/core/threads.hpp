#pragma once
// How many worker threads a run may ask for (`--jobs`, Python's jobs=): 0 means every core; more
// than kThreadsPerCore per core never makes a run faster, and a request far past that (100000)
// made the thread pool abort when the system refused to create the threads.
#include <cstddef>
#include <string>

namespace sextant {

inline constexpr std::size_t kThreadsPerCore = 4;

/// kThreadsPerCore × the cores this process may use (at least kThreadsPerCore).
std::size_t max_worker_threads();

/// Empty when `jobs` (0 = every core) can be honoured, else why not, naming `argument`.
std::string worker_threads_problem(long long jobs, const std::string& argument);

}  // namespace sextant
