#include "sextant/core/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace sextant {
namespace {

constexpr int kBarWidth = 30;
constexpr auto kRedrawInterval = std::chrono::milliseconds(100);

std::ostream* terminal_sink() {
  return (::isatty(STDOUT_FILENO) && ::isatty(STDERR_FILENO)) ? &std::cerr : nullptr;
}

}  // namespace

Progress::Progress(std::size_t total, std::string label)
    : Progress(total, std::move(label), terminal_sink()) {}

Progress::Progress(std::size_t total, std::string label, std::ostream* sink)
    : total_(total),
      label_(std::move(label)),
      sink_(sink),
      start_(std::chrono::steady_clock::now()),
      last_draw_() {}

Progress::~Progress() {
  finish();
}

void Progress::tick(std::size_t n) {
  done_ += n;
  if (!sink_ || finished_) return;
  std::unique_lock<std::mutex> lock(draw_mutex_, std::try_to_lock);
  if (!lock.owns_lock()) return;  // another thread is drawing; the next tick draws
  const auto now = std::chrono::steady_clock::now();
  if (now - last_draw_ < kRedrawInterval) return;
  last_draw_ = now;
  draw(false);
}

void Progress::finish() {
  if (finished_.exchange(true)) return;
  if (!sink_) return;
  std::lock_guard<std::mutex> lock(draw_mutex_);
  draw(true);
}

double Progress::eta_seconds() const {
  const std::size_t done = done_.load();
  if (done == 0) return -1.0;
  if (done >= total_) return 0.0;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  return elapsed / static_cast<double>(done) * static_cast<double>(total_ - done);
}

std::string Progress::line() const {
  const std::size_t done = done_.load();
  const double fraction =
      total_ == 0 ? 1.0 : std::min(1.0, static_cast<double>(done) / static_cast<double>(total_));
  const int filled = static_cast<int>(std::lround(fraction * kBarWidth));
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.resize(kBarWidth, ' ');
  char numbers[96];
  std::snprintf(numbers, sizeof numbers, " %zu/%zu %3.0f%%", done, total_, 100.0 * fraction);
  return label_ + " [" + bar + "]" + numbers + " ETA " + format_duration(eta_seconds());
}

void Progress::draw(bool final_line) {
  *sink_ << '\r' << line() << (final_line ? "\n" : "") << std::flush;
}

std::string format_duration(double seconds) {
  if (!(seconds >= 0.0) || !std::isfinite(seconds)) return "?";
  const long total = std::lround(seconds);
  char text[32];
  if (total >= 3600) {
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", total / 3600, (total / 60) % 60, total % 60);
  } else {
    std::snprintf(text, sizeof text, "%ld:%02ld", total / 60, total % 60);
  }
  return text;
}

}  // namespace sextant
