#pragma once
// A thread-safe progress bar with an ETA. It draws on stderr only when both stdout and stderr
// are terminals (so logs, pipes and CI stay quiet), at most ~10 times a second:
//
//   Progress progress(runs.size(), "e04 runs");
//   parallel_for(...) { ...; progress.tick(); }
//   progress.finish();   // final line; also done by the destructor
#include <atomic>
#include <chrono>
#include <cstddef>
#include <mutex>
#include <ostream>
#include <string>

namespace sextant {

class Progress {
 public:
  /// Draws only when stdout and stderr are terminals.
  Progress(std::size_t total, std::string label);
  /// Draws on `sink` (nullptr: never draws), whatever the terminal; for tests and tools.
  Progress(std::size_t total, std::string label, std::ostream* sink);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// Records n more finished items; safe from any thread.
  void tick(std::size_t n = 1);
  /// Draws the final state and a newline (once); later ticks are counted but not drawn.
  void finish();

  std::size_t done() const { return done_.load(); }
  std::size_t total() const { return total_; }
  /// Estimated seconds left from the mean rate so far; negative when unknown (nothing done yet).
  double eta_seconds() const;
  /// The line that would be drawn now, e.g. "e04 runs [#####     ] 50/100 50% ETA 0:12".
  std::string line() const;

 private:
  void draw(bool final_line);

  std::size_t total_;
  std::string label_;
  std::ostream* sink_;
  std::chrono::steady_clock::time_point start_;
  std::atomic<std::size_t> done_{0};
  std::atomic<bool> finished_{false};
  std::mutex draw_mutex_;
  std::chrono::steady_clock::time_point last_draw_;
};

/// "1:02:03" / "2:03" formatting of a duration [s]; "?" when negative.
std::string format_duration(double seconds);

}  // namespace sextant
