#pragma once
// Private to the runner: one writer per results folder. Two runner processes on the same
// results/<experiment>/ would both run the missing runs and interleave their rows; the second
// one is refused with a clear message instead (flock on results/<experiment>/.lock, released by
// the kernel when the holder exits, even after SIGKILL, so a stale lock never blocks a resume).
#include <filesystem>

namespace sextant::detail {

class ResultsLock {
 public:
  /// Creates `folder` if needed and takes its lock; InputError when the folder cannot be created
  /// or written, or when another process holds the lock.
  explicit ResultsLock(const std::filesystem::path& folder);
  ~ResultsLock();
  ResultsLock(const ResultsLock&) = delete;
  ResultsLock& operator=(const ResultsLock&) = delete;

 private:
  int fd_ = -1;
};

/// The lock file inside a results folder.
inline constexpr const char* kLockFile = ".lock";

}  // namespace sextant::detail
