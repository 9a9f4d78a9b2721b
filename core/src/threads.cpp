#include "sextant/core/threads.hpp"

#include <algorithm>
#include <thread>

namespace sextant {

std::size_t max_worker_threads() {
  return kThreadsPerCore * std::max<std::size_t>(1, std::thread::hardware_concurrency());
}

std::string worker_threads_problem(long long jobs, const std::string& argument) {
  if (jobs < 0)
    return argument + ": " + std::to_string(jobs) + " threads: give 0 (every core) or a positive count";
  if (static_cast<unsigned long long>(jobs) > max_worker_threads())
    return argument + ": " + std::to_string(jobs) + " threads on " +
           std::to_string(max_worker_threads() / kThreadsPerCore) + " cores: at most " +
           std::to_string(max_worker_threads()) + " (" + std::to_string(kThreadsPerCore) +
           " per core) can help; 0 uses every core";
  return "";
}

}  // namespace sextant
